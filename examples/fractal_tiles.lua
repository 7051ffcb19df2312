-- Seed 000, 17.2.3: fractal colourings. Two tiles, one coloured by the
-- Mandelbrot set and one by a Julia set, on a checkered table. The sets
-- lie in the texture's xy plane, so the tops of the tiles show them; scale
-- and translate fit them to the tiles.
local deep = {0.02, 0.03, 0.12}

-- The Mandelbrot set spans x from -2 to 0.5: scaled by 1.6 and moved so
-- that its middle, x = -0.75, sits over the tile's centre.
local mandel = box{size={4.4, 4.4, 0.3}, center=true}:translate(-2.6, 0, 0.15)
  :material{color=mandelbrot{colors={{0.05, 0.1, 0.45}, {1.0, 0.9, 0.35}}, inside=deep,
                             scale=1.6, translate={-2.6 + 0.75 * 1.6, 0, 0}},
            specular=0.2}

local rabbit = cylinder{r=2.2, h=0.3}:translate(2.6, 0, 0)
  :material{color=julia{c={-0.123, 0.745}, colors={{0.3, 0.05, 0.05}, {1.0, 0.95, 0.8}},
                        inside=deep, iterations=200, scale=1.4, translate={2.6, 0, 0}},
            specular=0.2}

local table = plane{normal={0, 0, 1}}
  :material{color=checker{size=1, colors={{0.8, 0.8, 0.78}, {0.55, 0.55, 0.53}}}}

return scene{
  objects = {table, mandel, rabbit},
  camera = camera{eye={0, -7, 8}, look_at={0, 0, 0}, fov=50},
  lights = {point_light{pos={-3, -5, 9}, intensity=0.9}, point_light{pos={5, -2, 6}, intensity=0.3}},
  background = {0.6, 0.7, 0.85},
}
