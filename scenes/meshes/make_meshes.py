#!/usr/bin/env python3
"""Writes the meshes the example scenes use (run from this folder; the output is committed).

plane.off       a 40 x 40 grid on [-2, 2]^2 in the plane y = 0, counter-clockwise seen from +y
                (3200 triangles): fine enough that per-vertex lighting shows a spotlight's cone.
hemisphere.obj  the lower half of the unit sphere, open at y = 0 (12 rings of 32 segments, 736
                triangles), counter-clockwise seen from outside, with its exact outward normals
                (`vn`): an open surface whose inside shows back faces.
"""
import math

def plane(n=40, size=4.0):
    verts = [(-size / 2 + size * i / n, 0.0, -size / 2 + size * j / n) for j in range(n + 1) for i in range(n + 1)]
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i          # (x_i, z_j)
            b, c, d = a + 1, a + n + 1, a + n + 2
            # Seen from +y with x right and z toward the viewer, a -> c -> b is counter-clockwise.
            faces += [(a, c, b), (b, c, d)]
    with open("plane.off", "w") as f:
        f.write("OFF\n")  # no comments: OpenMesh's OFF reader does not take them here
        f.write("%d %d 0\n" % (len(verts), len(faces)))
        for v in verts:
            f.write("%.6g %.6g %.6g\n" % v)
        for t in faces:
            f.write("3 %d %d %d\n" % t)

def hemisphere(rings=12, segments=32):
    verts = [(0.0, -1.0, 0.0)]  # the bottom pole
    for r in range(1, rings + 1):
        theta = math.pi / 2 * r / rings  # from the pole (0) to the rim (pi/2)
        for s in range(segments):
            phi = 2 * math.pi * s / segments
            verts.append((math.sin(theta) * math.cos(phi), -math.cos(theta), math.sin(theta) * math.sin(phi)))
    ring = lambda r, s: 1 + (r - 1) * segments + s % segments
    faces = []
    for s in range(segments):  # the cap around the pole
        faces.append((0, ring(1, s), ring(1, s + 1)))
    for r in range(1, rings):
        for s in range(segments):
            a, b = ring(r, s), ring(r, s + 1)
            c, d = ring(r + 1, s), ring(r + 1, s + 1)
            faces += [(a, d, b), (a, c, d)]
    with open("hemisphere.obj", "w") as f:
        f.write("# The lower half of the unit sphere, open at y = 0; outward normals; %d triangles\n" % len(faces))
        for v in verts:
            f.write("v %.6f %.6f %.6f\n" % v)
        for v in verts:
            f.write("vn %.6f %.6f %.6f\n" % v)
        for t in faces:
            f.write("f %s\n" % " ".join("%d//%d" % (i + 1, i + 1) for i in t))
    check_outward(verts, faces)

def check_outward(verts, faces):  # every triangle's normal points away from the centre
    for t in faces:
        a, b, c = (verts[i] for i in t)
        u = [b[k] - a[k] for k in range(3)]
        w = [c[k] - a[k] for k in range(3)]
        n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
        centre = [(a[k] + b[k] + c[k]) / 3 for k in range(3)]
        assert sum(n[k] * centre[k] for k in range(3)) > 0, t

plane()
hemisphere()
