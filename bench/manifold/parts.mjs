// The parts of bench/export_parts/*.lua built with Manifold's WebAssembly
// build (the npm package manifold-3d), with csgray's segment counts at the
// same chord tolerance, and written as a binary STL: the anchor of the
// export table in `make bench`.
//   node bench/manifold/parts.mjs <part> [n] -o out.stl
import Module from 'manifold-3d';
import {writeFileSync} from 'node:fs';

const wasm = await Module();
wasm.setup();
const {Manifold, CrossSection} = wasm;
const tolerance = 0.01;

// csgray's segment counts (tessellation/tessellation.cpp arcSegments,
// circleSegments and circlePolygon, and the primitives' objectTessellate).
function arcSegments(radius, angle, tol, min = 8) {
  if (!(radius > tol)) return min;
  const step = 2 * Math.acos(1 - tol / radius);
  return Math.max(min, Math.ceil(angle / step));
}
// Rounded up to m·2^k, m in 4..7.
function circleSegments(n) {
  let scale = 1;
  while (n > 8 * scale) scale *= 2;
  return Math.ceil(n / scale) * scale;
}
// A circle's polygon, made for nine tenths of the tolerance; its error.
function circlePolygon(r) {
  const shift = tolerance > 4e-9 * r ? 1e-9 : 0;
  const e = 0.9 * tolerance - 2 * shift * r;
  const segments = circleSegments(arcSegments(r, 2 * Math.PI, 2 * r * e / (r + e)));
  const c = Math.cos(Math.PI / segments);
  return {segments, error: r * (1 - c) / (1 + c) + 2 * shift * r};
}
// csgray's geodesic sphere of frequency f has 20 f² triangles, Manifold's
// sphere of n segments n²/2: n = √40 f, a multiple of 4. f as csgray picks
// it: from the largest triangle, raised by a tenth until the sphere's
// measured sag (the largest circumradius of a triangle of one face of the
// unit icosahedron cut f × f) is within the tolerance.
const phi = (1 + Math.sqrt(5)) / 2;
const face = [[-1, phi, 0], [-phi, 0, 1], [0, 1, phi]];  // csgray's face {0, 11, 5}
function geodesicSag(f) {
  const point = (i, j) => {
    const w = [f - i, i - j, j], p = [0, 0, 0];
    for (let k = 0; k < 3; ++k) for (let a = 0; a < 3; ++a) p[a] += w[k] * face[k][a];
    const l = Math.hypot(...p);
    return p.map(x => x / l);
  };
  const sub = (a, b) => a.map((x, k) => x - b[k]);
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  let worst = 0;
  const sag = (a, b, c) => {
    const rho = Math.hypot(...sub(b, a)) * Math.hypot(...sub(c, b)) * Math.hypot(...sub(a, c)) /
                (2 * Math.hypot(...cross(sub(b, a), sub(c, a))));
    worst = Math.max(worst, 1 - Math.sqrt(Math.max(0, 1 - rho * rho)));
  };
  for (let i = 0; i < f; ++i)
    for (let j = 0; j <= i; ++j) {
      sag(point(i, j), point(i + 1, j), point(i + 1, j + 1));
      if (j < i) sag(point(i, j), point(i + 1, j + 1), point(i, j + 1));
    }
  return worst;
}
function sphereSegments(r) {
  const edge = Math.sqrt(12 * r * Math.min(tolerance, r));
  let f = Math.max(2, Math.ceil(1.1071 * r / edge));
  for (;;) {
    const c = 1 - geodesicSag(f);
    if (r * (1 - c) / (1 + c) <= tolerance) break;
    f = Math.ceil(f * 1.1);
  }
  return 4 * Math.round(Math.sqrt(40) * f / 4);
}
// Minimax placement as csgray's: vertices k = 2/(1 + cos(π/n)) out.
const out = n => 2 / (1 + Math.cos(Math.PI / n));
function cylinder(r1, r2, h) {
  const n = circlePolygon(Math.max(r1, r2)).segments;
  return Manifold.cylinder(h, r1 * out(n), r2 * out(n), n);
}
function sphere(r) { return Manifold.sphere(r, sphereSegments(r)); }
// The turn on the circle polygon of R + r, the tube within what it leaves.
function torus(R, r) {
  const circle = circlePolygon(R + r);
  const chords = arcSegments(r, 2 * Math.PI, tolerance - circle.error, 8);
  return CrossSection.circle(r, chords).translate([R, 0]).revolve(circle.segments);
}
const box = (x, y, z) => Manifold.cube([x, y, z]);

const parts = {
  plate(n = 8) {
    const p = 100 / n, spheres = [], holes = [];
    for (let i = 0; i < n; ++i)
      for (let j = 0; j < n; ++j) {
        const x = p / 2 + i * p, y = p / 2 + j * p;
        spheres.push(sphere(0.32 * p).translate([x, y, 10]));
        holes.push(cylinder(0.2 * p, 0.2 * p, 20).translate([x, y, -1]));
      }
    return Manifold.union([box(100, 100, 10), ...spheres]).subtract(Manifold.union(holes));
  },
  shaft_on_hub() {
    return cylinder(30, 30, 30).add(cylinder(30, 30, 30).translate([0, 0, 30]));
  },
  two_frustums() {
    return cylinder(30, 25, 10).add(cylinder(25, 28, 10).translate([0, 0, 10]));
  },
  frustum_stack() {
    return Manifold.union(frustums(40, 0, 0));
  },
  vase() {
    const outer = Manifold.union(frustums(40, 0, 0));
    const inner = Manifold.union(frustums(40, 2, 2));
    return outer.subtract(inner).add(torus(radius(40) - 1, 1).translate([0, 0, 80]));
  },
  rounded_box() {
    const [x, y, z, r] = [40, 30, 20, 3];
    const list = [box(x, y - 2 * r, z - 2 * r).translate([0, r, r]),
                  box(x - 2 * r, y, z - 2 * r).translate([r, 0, r]),
                  box(x - 2 * r, y - 2 * r, z).translate([r, r, 0])];
    for (const cx of [r, x - r]) for (const cy of [r, y - r]) for (const cz of [r, z - r])
      list.push(sphere(r).translate([cx, cy, cz]));
    for (const cy of [r, y - r]) for (const cz of [r, z - r])
      list.push(cylinder(r, r, x - 2 * r).rotate([0, 90, 0]).translate([r, cy, cz]));
    for (const cx of [r, x - r]) for (const cz of [r, z - r])
      list.push(cylinder(r, r, y - 2 * r).rotate([-90, 0, 0]).translate([cx, r, cz]));
    for (const cx of [r, x - r]) for (const cy of [r, y - r])
      list.push(cylinder(r, r, z - 2 * r).translate([cx, cy, r]));
    return Manifold.union(list);
  },
  pixel_knob() {
    const glyph = ['X...X', 'XX..X', 'X.X.X', 'X..XX', 'X...X'], p = 2, pixels = [];
    glyph.forEach((line, row) => [...line].forEach((c, col) => {
      if (c === 'X') pixels.push(box(p, p, 2).translate([(col - 2.5) * p, (2.5 - row) * p - p, 9]));
    }));
    return cylinder(15, 15, 10).subtract(Manifold.union(pixels));
  },
  // Slices of the twist and segments of the turn as csgray makes them for
  // the tolerance (primitives/linear_extrusion_tessellation.cpp: helices
  // within a quarter of it; revolution_tessellation.cpp: the widest circle
  // within half of it). csgray also splits long edges of a twisted
  // profile, which Manifold does not: csgray's mesh is the larger.
  gear(twist = 30) {
    const tip = 62, angle = twist * Math.PI / 180;
    const slices = twist ? arcSegments(tip, angle, tolerance / 4, 1) : 1;
    const gear = new CrossSection([gearPoints()]).extrude(20, slices - 1, twist);
    const bore = cylinder(10, 10, 22).translate([0, 0, -1]).add(box(6, 4, 22).translate([7, -2, -1]));
    return gear.subtract(bore);
  },
  turned_vase() {
    const profile = vaseProfile(), reach = Math.max(...profile.map(p => p[0]));
    return new CrossSection([profile]).revolve(arcSegments(reach, 2 * Math.PI, tolerance / 2, 8));
  },
  knurled_knob() {
    const [R, H, f] = [15, 12, 2];
    const body = Manifold.union([cylinder(R, R, H - f), cylinder(R - f, R - f, H),
                                 torus(R - f, f).translate([0, 0, H - f])]);
    const grooves = [];
    for (let i = 0; i < 24; ++i)
      grooves.push(cylinder(0.6, 0.6, H - f).translate([R, 0, 0]).rotate([0, 0, i * 15]));
    return body.subtract(Manifold.union(grooves));
  },
};
// bench/parts/gear.lua's involute gear: the same 1 200 points.
function gearPoints() {
  const teeth = 60, module = 2, pitch = module * teeth / 2;
  const base = pitch * Math.cos(20 * Math.PI / 180);
  const tip = pitch + module, root = pitch - 1.25 * module, flank = 9;
  const involute = r => { const a = Math.sqrt(Math.max(0, (r / base) ** 2 - 1)); return a - Math.atan(a); };
  const half = Math.PI / (2 * teeth) + involute(pitch), points = [];
  const add = (r, angle) => points.push([r * Math.cos(angle), r * Math.sin(angle)]);
  for (let i = 0; i < teeth; ++i) {
    const c = 2 * Math.PI * i / teeth;
    for (let k = 0; k < flank; ++k) {
      const r = root + (tip - root) * k / (flank - 1);
      add(r, c - (half - involute(Math.max(r, base))));
    }
    for (let k = flank - 1; k >= 0; --k) {
      const r = root + (tip - root) * k / (flank - 1);
      add(r, c + (half - involute(Math.max(r, base))));
    }
    const from = c + half - involute(Math.max(root, base));
    const to = c + 2 * Math.PI / teeth - half + involute(Math.max(root, base));
    add(root, from + (to - from) / 3);
    add(root, from + 2 * (to - from) / 3);
  }
  return points;
}
// bench/parts/turned_vase.lua's 200-point profile.
function vaseProfile() {
  const n = 99, height = 120, points = [[0, 0]];
  const radius = z => 30 + 12 * Math.sin(z / 22) - 8 * Math.cos(z / 9) * (z / height);
  for (let k = 0; k < n; ++k) { const z = height * k / (n - 1); points.push([radius(z), z]); }
  for (let k = n - 1; k >= 0; --k) { const z = 3 + (height - 3) * k / (n - 1); points.push([radius(z) - 2, z]); }
  points.push([0, 3]);
  return points;
}
function radius(i) { return 20 + 6 * Math.sin(i * 0.25); }
function frustums(n, inset, lift) {
  const list = [];
  for (let i = 0; i < n; ++i)
    list.push(cylinder(radius(i) - inset, radius(i + 1) - inset, 2).translate([0, 0, 2 * i + lift]));
  return list;
}

// A binary STL of the mesh.
function writeStl(path, mesh) {
  const tris = mesh.numTri, buf = Buffer.alloc(84 + 50 * tris);
  buf.writeUInt32LE(tris, 80);
  const v = (k, a) => mesh.vertProperties[mesh.numProp * mesh.triVerts[3 * k + a]];
  for (let t = 0, o = 84; t < tris; ++t, o += 50)
    for (let a = 0; a < 3; ++a)
      for (let c = 0; c < 3; ++c)
        buf.writeFloatLE(mesh.vertProperties[mesh.numProp * mesh.triVerts[3 * t + a] + c],
                         o + 12 + 12 * a + 4 * c);
  writeFileSync(path, buf);
}

const args = process.argv.slice(2);
const outIndex = args.indexOf('-o');
const path = outIndex >= 0 ? args.splice(outIndex, 2)[1] : null;
const [name, n] = args;
if (!parts[name]) {
  console.error(`manifold parts: unknown part ${name}; one of ${Object.keys(parts).join(', ')}`);
  process.exit(2);
}
const part = n ? parts[name](Number(n)) : parts[name]();
const mesh = part.getMesh();
if (part.status() !== 'NoError') {
  console.error(`manifold parts: ${name}: ${part.status()}`);
  process.exit(1);
}
if (path) writeStl(path, mesh);
console.log(`${name}: ${mesh.numTri} triangles, volume ${part.volume().toFixed(3)}`);
