-- Ground fog (POV-Ray's fog_type 2): fog of full density up to z = offset,
-- thinning above it as 1 / (1 + (z - offset) / altitude)^2, so it fills
-- the valleys of a fractal landscape and leaves the peaks and the sky
-- clear. A level ray in the fog keeps exp(-d / distance) of what it sees
-- over a way d long; one above it, in thinner fog, more. The sky is a
-- gradient seen by direction (POV-Ray's sky_sphere with a color_map of
-- three stops): pale at the horizon (z = 0), deep blue straight up (z = 1).
local land = fractal_mountain{size = 100, levels = 6, roughness = 0.55, seed = 3, surface = true}
return scene{
  objects = {
    land:material{color = "olivedrab", diffuse = 0.85},
    plane{normal = {0, 0, 1}, offset = -12}:material{color = "darkolivegreen"},
  },
  lights = {point_light{pos = {-80, -120, 200}, intensity = 1}},
  camera = camera{eye = {150, -80, 25}, look_at = {50, 50, 5}, fov = 55},
  background = gradient{colors = {{0, {0.8, 0.85, 0.9}}, {0.3, {0.45, 0.6, 0.85}}, {1, {0.1, 0.2, 0.55}}}},
  fog = {color = {0.85, 0.87, 0.9}, distance = 25, offset = -6, altitude = 3},
}
