#!/usr/bin/env python3
"""Writes the mesh reader test files: a 2 x 3 x 4 box (volume 24) in every
format and variant, and the bad files, each broken in one way that
tests/meshio/mesh_reader_test.cpp names. Run from this folder."""
import io
import math
import struct
import zipfile

# The box [0,2]x[0,3]x[0,4]: 8 corners, 6 quads counter-clockwise seen
# from outside.
P = [(x, y, z) for x in (0, 2) for y in (0, 3) for z in (0, 4)]
QUADS = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
TRIS = [t for q in QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def write(name, data):
    with open(name, "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)


def ascii_stl(tris, points=P, name="box"):
    out = [f"solid {name}"]
    for t in tris:
        out += ["  facet normal 0 0 0", "    outer loop"]
        out += ["      vertex %s %s %s" % points[i] for i in t]
        out += ["    endloop", "  endfacet"]
    return "\n".join(out + [f"endsolid {name}", ""])


def binary_stl(tris, points=P, header=b"binary box", count=None):
    data = header.ljust(80, b" ") + struct.pack("<I", len(tris) if count is None else count)
    for t in tris:
        data += struct.pack("<3f", 0, 0, 0)
        for i in t:
            data += struct.pack("<3f", *points[i])
        data += b"\0\0"
    return data


def obj(faces, points=P, extra=""):
    out = ["# a box", "o box", extra] + ["v %s %s %s" % p for p in points]
    out += ["vn 0 0 1", "vt 0 0"]
    out += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return "\n".join(out) + "\n"


def off(faces, points=P):
    out = ["OFF", "# a box", f"{len(points)} {len(faces)} 0"]
    out += ["%s %s %s" % p for p in points]
    out += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    return "\n".join(out) + "\n"


def ply(fmt, faces=QUADS, points=P, vertex_count=None, face_count=None):
    endian = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
    head = ["ply", f"format {fmt} 1.0", "comment a box with extra properties",
            f"element vertex {len(points) if vertex_count is None else vertex_count}",
            "property float x", "property float y", "property double z",
            "property uchar red", "property list uchar float extra",
            f"element face {len(faces) if face_count is None else face_count}",
            "property list uchar int vertex_indices", "property short flags",
            "element note 1", "property int value", "end_header"]
    data = ("\n".join(head) + "\n").encode()
    if endian is None:
        for p in points:
            data += ("%s %s %s 7 2 0.5 0.25\n" % p).encode()
        for f in faces:
            data += (f"{len(f)} " + " ".join(map(str, f)) + " 0\n").encode()
        return data + b"42\n"
    for p in points:
        data += struct.pack(endian + "ffdBBff", *p, 7, 2, 0.5, 0.25)
    for f in faces:
        data += struct.pack(endian + "B%dih" % len(f), len(f), *f, 0)
    return data + struct.pack(endian + "i", 42)


def threemf(model_body):
    """A 3MF package (a zip of three parts) holding the model; the box is
    object 1. Fixed dates, so the bytes are the same each run."""
    vertices = "".join('<vertex x="%s" y="%s" z="%s"/>' % p for p in P)
    triangles = "".join('<triangle v1="%d" v2="%d" v3="%d"/>' % t for t in TRIS)
    model = ('<?xml version="1.0" encoding="UTF-8"?>\n'
             '<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">'
             f'<resources><object id="1" type="model"><mesh><vertices>{vertices}</vertices>'
             f'<triangles>{triangles}</triangles></mesh></object>{model_body}</model>')
    parts = {
        "[Content_Types].xml":
            '<?xml version="1.0" encoding="UTF-8"?>\n<Types xmlns="http://schemas.openxmlformats.org/'
            'package/2006/content-types"><Default Extension="rels" ContentType="application/'
            'vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" '
            'ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>',
        "_rels/.rels":
            '<?xml version="1.0" encoding="UTF-8"?>\n<Relationships xmlns="http://schemas.'
            'openxmlformats.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" '
            'Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>'
            '</Relationships>',
        "3D/3dmodel.model": model,
    }
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        for name, text in parts.items():
            z.writestr(zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0)), text)
    return out.getvalue()


# Good files: the same box.
write("box_ascii.stl", ascii_stl(TRIS))
write("box_binary.stl", binary_stl(TRIS))
write("box_solid_header.stl", binary_stl(TRIS, header=b"solid box, but binary"))
write("box.obj", "\n".join(["# a box with texture and normal indices, negative and positive"]
                           + ["v %s %s %s" % p for p in P] + ["vt 0 0", "vn 0 0 1", "g box",
                           "f 1/1 2/1 4/1 3/1", "f 5//1 7//1 8//1 6//1", "f -8/1/1 -4/1/1 -3/1/1 -7/1/1",
                           "f 3 4 8 7", "usemtl grey", "f 1 3 7 5", "f 2 6 8 4"]) + "\n")
write("box.off", off(QUADS))
write("box_ascii.ply", ply("ascii"))
write("box_le.ply", ply("binary_little_endian"))
write("box_be.ply", ply("binary_big_endian"))
# An L-shaped hexagon prism: non-convex faces that need ear clipping.
L = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 2), (0, 2)]  # area 4, counter-clockwise
LP = [(x, y, 0) for x, y in L] + [(x, y, 5) for x, y in L]
LF = [tuple(reversed(range(6))), tuple(range(6, 12))] + [(i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6) for i in range(6)]
write("l_prism.obj", obj(LF, LP))  # volume 20

# Bad files.
write("empty.stl", "")
write("truncated_binary.stl", binary_stl(TRIS, count=12)[:84 + 50 * 5])
write("huge_count.stl", binary_stl(TRIS[:1], count=0xFFFFFFFF))
write("solid_header_wrong_size.stl", binary_stl(TRIS, header=b"solid box")[:-7])
write("short.stl", b"\x01\x02\x03")
write("truncated_ascii.stl", "\n".join(ascii_stl(TRIS).split("\n")[:40]) + "\n")
write("nan.stl", ascii_stl(TRIS).replace("vertex 0 3 0", "vertex nan 3 0", 1))
inf_points = list(P)
inf_points[7] = (2, 3, math.inf)
write("inf_binary.stl", binary_stl(TRIS, inf_points))
write("two_vertex_facet.stl", ascii_stl(TRIS).replace("      vertex 0 0 4\n", "", 1))
write("no_endsolid.stl", ascii_stl(TRIS).replace("endsolid box\n", ""))
write("out_of_range.obj", obj(QUADS).replace("f 2 6 8 4", "f 2 6 9 4"))
write("index_zero.obj", obj(QUADS).replace("f 2 6 8 4", "f 2 6 0 4"))
write("negative_out_of_range.obj", obj(QUADS).replace("f 2 6 8 4", "f -2 -6 -9 -4"))
write("two_corner_face.obj", obj(QUADS).replace("f 2 6 8 4", "f 2 6"))
write("bad_number.obj", obj(QUADS).replace("v 2 3 4", "v 2 3 four"))
write("wrong_count.off", off(QUADS).replace("8 6 0", "10 6 0"))
write("huge_count.off", off(QUADS).replace("8 6 0", "100000000 6 0"))
write("out_of_range.off", off(QUADS).replace("4 1 5 7 3", "4 1 5 8 3"))
write("truncated_le.ply", ply("binary_little_endian")[:-30])
write("huge_count.ply", ply("binary_little_endian", vertex_count=4000000000))
write("out_of_range_ascii.ply", ply("ascii").replace(b"4 1 5 7 3 0", b"4 1 5 70 3 0"))
write("inf_be.ply", ply("binary_big_endian", points=inf_points))
write("no_faces.ply", ply("ascii", faces=[]))
# Not solids.
write("open.obj", obj(QUADS[:-1]))
write("flipped_face.obj", obj(QUADS[:-1] + [tuple(reversed(QUADS[-1]))]))
write("inside_out.off", off([tuple(reversed(q)) for q in QUADS]))
write("duplicated_facet.stl", ascii_stl(TRIS + [TRIS[3]]))
write("degenerate_facet.stl", ascii_stl(TRIS + [(0, 0, 1)]))
# Two boxes that share an edge: non-manifold there.
Q = [(x + 2, y + 3, z) for x, y, z in P]
write("shared_edge.obj", obj(QUADS + [tuple(i + 8 for i in q) for q in QUADS], P + Q))
# Two overlapping boxes in one file.
R = [(x + 1, y + 1, z + 1) for x, y, z in P]
write("overlapping.obj", obj(QUADS + [tuple(i + 8 for i in q) for q in QUADS], P + R))
# 3MF: the box in a components object (moved by 5 along x), placed by a
# build item turned 90 degrees about z and moved by (10, 20, 30); and the
# box itself mirrored in x (its faces must turn back outward).
placed = threemf('<object id="2" type="model"><components><component objectid="1" '
                 'transform="1 0 0 0 1 0 0 0 1 5 0 0"/></components></object></resources>'
                 '<build><item objectid="2" transform="0 1 0 -1 0 0 0 0 1 10 20 30"/>'
                 '<item objectid="1" transform="-1 0 0 0 1 0 0 0 1 0 0 0"/></build>')
write("placed_components.3mf", placed)
write("truncated.3mf", placed[: len(placed) // 2])
