#!/usr/bin/env python3
"""Writes the hand-made seeds of fuzz/corpus/: the shipped scenes, small scenes that use every key,
and small meshes in each format (ASCII and binary variants, normals, quads, negative OBJ indices).
Crashers the fuzzers find are added to the corpus by hand, minimized (see README.md)."""
import os
import shutil
import struct

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(here)


def write(target, name, data):
    d = os.path.join(here, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


# --- scenes: the shipped ones, and every key of the schema (src/scene/file.cpp)
for n in sorted(os.listdir(os.path.join(root, "scenes"))):
    if n.endswith(".toml"):
        shutil.copy(os.path.join(root, "scenes", n), os.path.join(here, "corpus", "fuzz_scene_file", n))
write("fuzz_scene_file", "minimal.toml", '[[mesh]]\nsource = "cube"\n')
write("fuzz_scene_file", "every_key.toml", '''name = "every key"
size = [64, 48]
background = [0.1, 0.2, 0.3, 1]
shade = "flat"
lighting = true
depth_test = true
normalize = true
rescale_normal = false
cull_face = "back"
front_face = "cw"
axes = true
transforms = [{ rotate = [30, 0, 1, 0] }, { translate = [0, 0, -1] }, { scale = [1, 2, 1] }]

[camera]
projection = "frustum"
left = -1
right = 1
bottom = -1
top = 1
near = 1
far = 10
eye = [0, 0, 5]
center = [0, 0, 0]
up = [0, 1, 0]

[light_model]
ambient = [0.2, 0.2, 0.2, 1]
local_viewer = true
two_sided = true
separate_specular = true

[material]
ambient_and_diffuse = [1, 0, 0]
specular = [1, 1, 1, 1]
emission = [0, 0, 0, 1]
shininess = 128
[material.front]
shininess = 0
[material.back]
diffuse = [0, 0, 1]

[color_material]
enabled = true
face = "back"
mode = "emission"

[[light]]
index = 7
enabled = true
ambient = [0, 0, 0, 1]
diffuse = [1, 1, 1, 1]
specular = [1, 1, 1, 1]
position = [1, 2, 3, 1]
space = "world"
spot_direction = [0, 0, -1]
spot_exponent = 128
spot_cutoff = 90
constant_attenuation = 0
linear_attenuation = 1e-3
quadratic_attenuation = 1e38

[[mesh]]
source = "icosphere:12"
normals = "average"
draw = "immediate"
color = [1, 0.5, 0.25, 1]
transforms = [{ scale = [0, 0, 0] }]
material = { shininess = 5 }

[[mesh]]
source = "meshes/plane.off"
normals = "file"
draw = "elements"
color = "position"

[[mesh]]
source = "meshes/hemisphere.obj"
normals = "face"
draw = "arrays"
color = "normal"
''')
write("fuzz_scene_file", "perspective_ortho.toml", '''[camera]
projection = "perspective"
fovy = 179.9
aspect = 1e-30
near = 1e-30
far = 1e30
[[mesh]]
source = "icosphere"
[[mesh]]
source = "icosphere:0"
draw = "auto"
''')

# --- meshes, one corpus per format
tetra_v = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
tetra_f = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
obj = "".join("v %g %g %g\n" % v for v in tetra_v) + "".join("f %d %d %d\n" % tuple(i + 1 for i in f) for f in tetra_f)
write("fuzz_mesh_obj", "tetra.obj", obj)
write("fuzz_mesh_obj", "normals.obj", "# a tetrahedron with normals and texture coordinates\n" +
      "".join("v %g %g %g\n" % v for v in tetra_v) + "vt 0 0\nvt 1 0\nvt 0 1\n" +
      "vn 0 0 -1\nvn 0 -1 0\nvn -1 0 0\nvn 0.577 0.577 0.577\ng tetra\ns 1\nusemtl none\n" +
      "f 1/1/1 3/2/1 2/3/1\nf 1//2 2//2 4//2\nf 1/1 4/2 3/3\nf -3/-3/-1 -2/-2/-1 -1/-1/-1\n")
write("fuzz_mesh_obj", "quad_negative.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0 1\nf -4 -3 -2 -1\n")

off = "OFF\n4 4 6\n" + "".join("%g %g %g\n" % v for v in tetra_v) + "".join("3 %d %d %d\n" % f for f in tetra_f)
write("fuzz_mesh_off", "tetra.off", off)
write("fuzz_mesh_off", "normals.noff", "NOFF\n4 2 0\n-1 -1 0 0 0 1\n1 -1 0 0 0 1\n1 1 0 0 0 1\n-1 1 0 0 0 1\n"
      "3 0 1 2\n3 0 2 3\n")
write("fuzz_mesh_off", "quad_colour.off", "COFF\n4 1 0\n-1 -1 0 255 0 0 255\n1 -1 0 0 255 0 255\n"
      "1 1 0 0 0 255 255\n-1 1 0 255 255 255 255\n4 0 1 2 3\n")

ply_header = "ply\nformat %s 1.0\ncomment seed\nelement vertex 4\nproperty float x\nproperty float y\n" \
             "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n" \
             "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
normals = [(-0.577, -0.577, -0.577), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
write("fuzz_mesh_ply", "tetra_ascii.ply", ply_header % "ascii" +
      "".join("%g %g %g %g %g %g\n" % (v + n) for v, n in zip(tetra_v, normals)) +
      "".join("3 %d %d %d\n" % f for f in tetra_f))
for name, fmt, e in (("tetra_le.ply", "binary_little_endian", "<"), ("tetra_be.ply", "binary_big_endian", ">")):
    body = b"".join(struct.pack(e + "6f", *(v + n)) for v, n in zip(tetra_v, normals))
    body += b"".join(struct.pack(e + "B3i", 3, *f) for f in tetra_f)
    write("fuzz_mesh_ply", name, (ply_header % fmt).encode() + body)
write("fuzz_mesh_ply", "quad_short_list.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\n"
      "property double y\nproperty double z\nelement face 1\nproperty list ushort uint vertex_index\n"
      "end_header\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n4 0 1 2 3\n")


def cross(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


stl = "solid tetra\n"
for f in tetra_f:
    a, b, c = (tetra_v[i] for i in f)
    stl += "  facet normal %g %g %g\n    outer loop\n" % cross(a, b, c)
    stl += "".join("      vertex %g %g %g\n" % v for v in (a, b, c)) + "    endloop\n  endfacet\n"
write("fuzz_mesh_stl", "tetra_ascii.stl", stl + "endsolid tetra\n")
binary = b"binary seed".ljust(80, b" ") + struct.pack("<I", len(tetra_f))
for f in tetra_f:
    a, b, c = (tetra_v[i] for i in f)
    binary += struct.pack("<12fH", *cross(a, b, c), *a, *b, *c, 0)
write("fuzz_mesh_stl", "tetra_binary.stl", binary)
