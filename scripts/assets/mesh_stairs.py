#!/usr/bin/env python3
"""Generate a mesh-only environment for extracted surfaces (`surfaces: auto`,
docs/SURFACE_FORMAT.md):

    assets/environments/mesh_stairs/   a floor slab and a staircase up to a platform, as meshes

    python3 scripts/assets/mesh_stairs.py

Our own model, same conventions as scripts/generate_assets.py (x forward, y left, z up, metres,
kilograms). No box and no surface file: the link `floor` is a slab mesh (floor.stl) and the link
`stairs` is ONE mesh (stairs_platform.stl) holding four steps and the platform they lead to, so
that every contact surface has to be extracted from triangles. The treads, risers and platform
top are tessellated in cells of at most 0.1 m (a tread is 60 triangles), and each side of the
flight is one non-convex staircase outline: what extraction has to merge and split. The floor is a
mesh of its own because the collision model takes a mesh's convex hull (planner/collision): a hull
of floor and stairs together would cover the floor in front of the first step. ASCII STL,
deterministic output.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import generate_assets as g  # noqa: E402

THIS = "scripts/assets/mesh_stairs.py"
FOLDER = "environments/mesh_stairs"

STAIRS = dict(
    start=0.35,     # x of the first riser: the humanoid stands at the origin, toes at x = 0.14
    steps=4,        # steps below the platform
    rise=0.10,      # height of every step and of the platform above the last one
    tread=0.30,     # depth (x) of every tread
    platform=0.80,  # depth of the platform (top at (steps + 1) x rise)
    width=1.00,     # y, centred on y = 0
    cell=0.10,      # largest side of a tessellation cell
)
FLOOR = dict(size=(8.0, 6.0, 0.05), center_xy=(1.5, 0.0))  # as the other environments' floor
DENSITY = dict(floor=1000.0, wood=600.0)


def levels():
    """(x near, x far, top z) of every tread, the platform last."""
    s = STAIRS
    out = []
    for k in range(1, s["steps"] + 2):
        near = s["start"] + (k - 1) * s["tread"]
        depth = s["platform"] if k == s["steps"] + 1 else s["tread"]
        out.append((near, near + depth, k * s["rise"]))
    return out


def splits(a, b):
    """Points from a to b at most STAIRS['cell'] apart."""
    n = max(1, int(math.ceil(abs(b - a) / STAIRS["cell"] - 1e-9)))
    return [a + (b - a) * i / n for i in range(n + 1)]


def grid(corner, du, dv):
    """Triangles of the parallelogram corner + [0, 1] du + [0, 1] dv in cells, counter-clockwise
    about du x dv."""
    us = splits(0.0, math.sqrt(g.vdot(du, du)))
    vs = splits(0.0, math.sqrt(g.vdot(dv, dv)))
    eu = g.vscale(du, 1.0 / us[-1])
    ev = g.vscale(dv, 1.0 / vs[-1])

    def p(u, v):
        return g.vadd(corner, g.vadd(g.vscale(eu, u), g.vscale(ev, v)))

    tris = []
    for i in range(len(us) - 1):
        for j in range(len(vs) - 1):
            a, b = p(us[i], vs[j]), p(us[i + 1], vs[j])
            c, d = p(us[i + 1], vs[j + 1]), p(us[i], vs[j + 1])
            tris += [(a, b, c), (a, c, d)]
    return tris


def side(y, outward):
    """One side of the flight (the staircase outline in the plane y): per level, a column from the
    floor to its tread whose near edge also has the corner of the level below, fanned from its far
    bottom corner so that every triangle has an area."""
    tris = []
    below = 0.0
    for near, far, top in levels():
        fan = [(far, y, 0.0), (far, y, top), (near, y, top)]
        if below > 0.0:
            fan.append((near, y, below))
        fan.append((near, y, 0.0))
        for i in range(1, len(fan) - 1):
            t = (fan[0], fan[i], fan[i + 1])  # counter-clockwise about -y
            tris.append(t if outward < 0 else (t[0], t[2], t[1]))
        below = top
    return tris


def stairs_triangles():
    w = STAIRS["width"]
    tris = []
    below = 0.0
    for near, far, top in levels():
        tris += grid((near, -w / 2, top), (far - near, 0.0, 0.0), (0.0, w, 0.0))      # tread, +z
        tris += grid((near, w / 2, below), (0.0, -w, 0.0), (0.0, 0.0, top - below))  # riser, -x
        below = top
    x0, x1, top = levels()[0][0], levels()[-1][1], levels()[-1][2]
    tris += grid((x1, -w / 2, 0.0), (0.0, w, 0.0), (0.0, 0.0, top))  # back, +x
    tris += grid((x0, w / 2, 0.0), (x1 - x0, 0.0, 0.0), (0.0, -w, 0.0))  # bottom, -z
    tris += side(-w / 2, -1) + side(w / 2, +1)
    return tris


def box_triangles(size, center):
    """The 12 triangles of an axis-aligned box, counter-clockwise seen from outside."""
    h = g.vscale(size, 0.5)
    lo = g.vsub(center, h)
    sx, sy, sz = size
    X, Y, Z = (sx, 0.0, 0.0), (0.0, sy, 0.0), (0.0, 0.0, sz)
    hi = g.vadd(lo, g.vadd(X, g.vadd(Y, Z)))
    faces = [(lo, Y, X), (lo, X, Z), (lo, Z, Y),                  # -z, -y, -x
             (hi, g.vscale(X, -1), g.vscale(Y, -1)),              # +z
             (hi, g.vscale(Z, -1), g.vscale(X, -1)),              # +y
             (hi, g.vscale(Y, -1), g.vscale(Z, -1))]              # +x
    tris = []
    for corner, du, dv in faces:
        a, b, c, d = corner, g.vadd(corner, du), g.vadd(corner, g.vadd(du, dv)), g.vadd(corner, dv)
        tris += [(a, b, c), (a, c, d)]
    return tris


def check_outward(tris, inside):
    """Every triangle's normal points away from a point inside the (star-shaped) solid."""
    for a, b, c in tris:
        n = g.vcross(g.vsub(b, a), g.vsub(c, a))
        assert math.sqrt(g.vdot(n, n)) > 1e-12, (a, b, c)
        centroid = g.vscale(g.vadd(a, g.vadd(b, c)), 1.0 / 3.0)
        assert g.vdot(n, g.vsub(centroid, inside)) > 0.0, (a, b, c)


def stl(name, tris):
    out = [f"solid {name}"]
    for a, b, c in tris:
        n = g.vcross(g.vsub(b, a), g.vsub(c, a))
        length = math.sqrt(g.vdot(n, n))
        out.append(f"  facet normal {g.fvec(g.vscale(n, 1.0 / length), 9)}")
        out.append("    outer loop")
        for p in (a, b, c):
            out.append(f"      vertex {g.fvec(p, 9)}")
        out.append("    endloop")
        out.append("  endfacet")
    out.append(f"endsolid {name}")
    return "\n".join(out) + "\n"


def mesh_link(name, mesh, mass, com, dims, material, doc):
    """A link whose visual and collision geometry is one mesh file; the inertia of a box of dims."""
    a, b, c = dims
    ixx, iyy, izz = (mass * (b * b + c * c) / 12.0, mass * (a * a + c * c) / 12.0,
                     mass * (a * a + b * b) / 12.0)
    return "\n".join([
        f"  <!-- {doc} -->",
        f'  <link name="{name}">',
        "    <inertial>",
        f'      <origin xyz="{g.fvec(com)}" rpy="0 0 0"/>',
        f'      <mass value="{g.fnum(mass, 4)}"/>',
        f'      <inertia ixx="{g.fsci(ixx)}" ixy="0" ixz="0" iyy="{g.fsci(iyy)}" iyz="0" izz="{g.fsci(izz)}"/>',
        "    </inertial>",
        "    <visual>",
        f'      <geometry><mesh filename="{mesh}"/></geometry>',
        f'      <material name="{material}"/>',
        "    </visual>",
        f'    <collision name="{name}">',
        f'      <geometry><mesh filename="{mesh}"/></geometry>',
        "    </collision>",
        "  </link>",
    ])


def urdf():
    s, lv = STAIRS, levels()
    x0, x1, top = lv[0][0], lv[-1][1], lv[-1][2]
    volume = sum((far - near) * top_k * s["width"] for near, far, top_k in lv)
    com_x = sum((near + far) / 2 * (far - near) * top_k for near, far, top_k in lv) / (volume / s["width"])
    sx, sy, sz = FLOOR["size"]
    lines = [
        '<?xml version="1.0"?>',
        "<!-- mesh_stairs: stanceplan environment (fixed, root link floor) with no box and no surface file: its",
        "     contact surfaces are extracted from the meshes (surfaces: auto). -->",
        f"<!-- Generated by {THIS} - do not edit by hand; change the script instead. -->",
        f"<!-- {s['steps']} steps of {g.fnum(s['rise'])} m from x = {g.fnum(x0)} m, treads {g.fnum(s['tread'])} m deep, up to a "
        f"platform at z = {g.fnum(top)} m from x = {g.fnum(lv[-1][0])} to {g.fnum(x1)} m; {g.fnum(s['width'])} m wide (y); "
        "floor top at z = 0. -->",
        '<robot name="mesh_stairs">',
        "",
    ]
    lines += [f'  <material name="{n}"><color rgba="{g.fvec(c, 3)}"/></material>'
              for n, c in g.ENV_MATERIALS if n in ("floor_light", "wood")]
    lines += ["", mesh_link("floor", "floor.stl", DENSITY["floor"] * sx * sy * sz, (FLOOR["center_xy"][0], 0.0, -sz / 2),
                            FLOOR["size"], "floor_light",
                            f"floor slab {g.fnum(sx)} x {g.fnum(sy)} x {g.fnum(sz)} m, top face at z = 0 (floor.stl)")]
    lines += ["", '  <joint name="floor_to_stairs" type="fixed">', '    <parent link="floor"/>',
              '    <child link="stairs"/>', '    <origin xyz="0 0 0" rpy="0 0 0"/>', "  </joint>"]
    lines += [mesh_link("stairs", "stairs_platform.stl", DENSITY["wood"] * volume, (com_x, 0.0, top / 2),
                        (x1 - x0, s["width"], top), "wood",
                        "the steps and the platform: one mesh (stairs_platform.stl), world coordinates")]
    lines += ["", "</robot>"]
    return "\n".join(lines) + "\n"


def readme():
    rows = []
    for k, (near, far, top) in enumerate(levels(), start=1):
        what = "platform" if k == len(levels()) else f"tread {k}"
        rows.append(f"| `support_{k}` | {what} | {g.fnum(near)} to {g.fnum(far)} | {g.fnum(top)} |")
    return "\n".join([
        "# mesh_stairs: a staircase and its platform as one mesh, for extracted surfaces",
        "",
        f"Written by `{THIS}` (do not edit by hand). Fixed, root link `floor` (a slab mesh, `floor.stl`,",
        "top at z = 0, the size of the other environments' floor); link `stairs` is ONE mesh,",
        f"`stairs_platform.stl`: {STAIRS['steps']} steps of {g.fnum(STAIRS['rise'])} m and the platform they lead to,",
        f"{g.fnum(STAIRS['width'])} m wide (y from {g.fnum(-STAIRS['width'] / 2)} to {g.fnum(STAIRS['width'] / 2)} m). There is no surface file:",
        "a scenario gives the environment `surfaces: auto` (docs/SURFACE_FORMAT.md, \"Extracted",
        "surfaces\"), which names the supports by height:",
        "",
        "| surface | what | x (m) | top z (m) |",
        "|---|---|---|---|",
        "| `support_0` | floor | -2.5 to 5.5 | 0 |",
    ] + rows + [
        "",
        "The risers, sides, back and the floor's edges are `lean_*` surfaces. Used by",
        "`tests/data/affordances/mesh_stairs.yaml`.",
        "",
    ])


def main():
    sx, sy, sz = FLOOR["size"]
    cx, cy = FLOOR["center_xy"]
    floor = box_triangles((sx, sy, sz), (cx, cy, -sz / 2))
    check_outward(floor, (cx, cy, -sz / 2))
    stairs = stairs_triangles()
    # The flight is not star-shaped: a point just behind each face (against its normal) must be
    # inside the solid, one just in front of it outside.
    def solid(p):
        return abs(p[1]) < STAIRS["width"] / 2 and 0.0 < p[2] and any(
            near < p[0] < far and p[2] < top for near, far, top in levels())

    for a, b, c in stairs:
        n = g.vcross(g.vsub(b, a), g.vsub(c, a))
        length = math.sqrt(g.vdot(n, n))
        assert length > 1e-12, (a, b, c)
        centroid = g.vscale(g.vadd(a, g.vadd(b, c)), 1.0 / 3.0)
        step = g.vscale(n, 1e-4 / length)
        assert solid(g.vsub(centroid, step)) and not solid(g.vadd(centroid, step)), (a, b, c)
    written = []
    g.write(f"{FOLDER}/floor.stl", stl("floor", floor), written)
    g.write(f"{FOLDER}/stairs_platform.stl", stl("stairs_platform", stairs), written)
    g.write(f"{FOLDER}/mesh_stairs.urdf", urdf(), written)
    g.write(f"{FOLDER}/README.md", readme(), written)
    for p in written:
        print("wrote", p, f"({len(floor)} + {len(stairs)} triangles)" if p.endswith("urdf") else "")
    return 0


if __name__ == "__main__":
    sys.exit(main())
