#!/usr/bin/env python3
"""Generate stanceplan's own robot and environment models (URDF + surface files + README).

Everything in assets/robots/humanoid and assets/environments/* is written by this script from the
parameters below; nothing is copied from other models. Python 3 standard library only.

    python3 scripts/generate_assets.py            # write the files, print a short check report
    python3 scripts/generate_assets.py --check    # also print every clearance found

The output is deterministic: running the script twice gives byte-identical files.

Conventions (all models): x forward, y left, z up, metres, kilograms, radians. Every humanoid joint
origin has rpy = 0, so at the zero configuration every link frame is parallel to the waist frame.
Inertias are those of uniform-density solids (box, cylinder, sphere) combined with the parallel-axis
theorem; each link's mass is set explicitly and spread over its shapes by volume.
"""

import argparse
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ASSETS = os.path.join(ROOT, "assets")

# ------------------------------------------------------------------------------------------------
# Number formatting (fixed, so that the output never depends on the platform)


def fnum(x, digits=6):
    """Plain decimal with at most `digits` decimals, no trailing zeros, never '-0'."""
    v = round(float(x), digits)
    if v == 0.0:
        return "0"
    s = f"{v:.{digits}f}".rstrip("0").rstrip(".")
    return s


def fsci(x):
    """Inertia entries: 6 significant digits (may use an exponent)."""
    if abs(x) < 1e-15:
        return "0"
    return f"{x:.6g}"


def fvec(v, digits=6):
    return " ".join(fnum(c, digits) for c in v)


def yvec(v, digits=6):
    return "[" + ", ".join(fnum(c, digits) for c in v) + "]"


# ------------------------------------------------------------------------------------------------
# Small linear algebra (3-vectors as tuples, 3x3 matrices as tuples of rows)


def vadd(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vscale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def vcross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def mmul(A, B):
    return tuple(tuple(sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)) for i in range(3))


def mvec(A, v):
    return tuple(A[i][0] * v[0] + A[i][1] * v[1] + A[i][2] * v[2] for i in range(3))


def mcol(A, j):
    return (A[0][j], A[1][j], A[2][j])


IDENTITY = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def axis_angle(axis, q):
    x, y, z = axis
    c, s = math.cos(q), math.sin(q)
    t = 1.0 - c
    return ((t * x * x + c, t * x * y - s * z, t * x * z + s * y),
            (t * x * y + s * z, t * y * y + c, t * y * z - s * x),
            (t * x * z - s * y, t * y * z + s * x, t * z * z + c))


AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}

# ------------------------------------------------------------------------------------------------
# Materials

ROBOT_MATERIALS = [
    ("body_light", (0.84, 0.85, 0.87, 1.0)),   # shells
    ("joint_dark", (0.22, 0.23, 0.26, 1.0)),   # actuators, hands, soles
    ("accent_blue", (0.13, 0.36, 0.78, 1.0)),  # stripes, chest plate, fingers
]
ENV_MATERIALS = [
    ("floor_light", (0.90, 0.89, 0.86, 1.0)),
    ("wood", (0.62, 0.44, 0.26, 1.0)),
    ("wood_dark", (0.45, 0.31, 0.18, 1.0)),
    ("wall_paint", (0.80, 0.83, 0.80, 1.0)),
]

# ------------------------------------------------------------------------------------------------
# Model description


class Shape:
    """One primitive of a link. dims: box (sx, sy, sz); cylinder (radius, length); sphere (radius,).
    A cylinder's axis is one of the link axes 'x', 'y', 'z'."""

    def __init__(self, kind, dims, xyz=(0.0, 0.0, 0.0), axis="z", material="body_light",
                 collision=False, visual=True, inertial=True, name=None):
        self.kind, self.dims, self.xyz, self.axis = kind, tuple(dims), tuple(xyz), axis
        self.material, self.collision, self.visual, self.inertial = material, collision, visual, inertial
        self.name = name

    def volume(self):
        if self.kind == "box":
            return self.dims[0] * self.dims[1] * self.dims[2]
        if self.kind == "cylinder":
            return math.pi * self.dims[0] ** 2 * self.dims[1]
        return 4.0 / 3.0 * math.pi * self.dims[0] ** 3

    def inertia_diag(self, m):
        """Principal moments about the shape's centre, in the link axes."""
        if self.kind == "box":
            a, b, c = self.dims
            return (m * (b * b + c * c) / 12.0, m * (a * a + c * c) / 12.0, m * (a * a + b * b) / 12.0)
        if self.kind == "cylinder":
            r, h = self.dims
            ia, ip = m * r * r / 2.0, m * (3.0 * r * r + h * h) / 12.0
            return tuple(ia if k == self.axis else ip for k in "xyz")
        r = self.dims[0]
        return (0.4 * m * r * r,) * 3

    def rpy(self):
        if self.kind != "cylinder" or self.axis == "z":
            return (0.0, 0.0, 0.0)
        return (math.pi / 2.0, 0.0, 0.0) if self.axis == "y" else (0.0, math.pi / 2.0, 0.0)

    def half(self):
        """Half extents of the box (boxes only)."""
        return (self.dims[0] / 2.0, self.dims[1] / 2.0, self.dims[2] / 2.0)

    def geometry_xml(self):
        if self.kind == "box":
            return f'<box size="{fvec(self.dims)}"/>'
        if self.kind == "cylinder":
            return f'<cylinder radius="{fnum(self.dims[0])}" length="{fnum(self.dims[1])}"/>'
        return f'<sphere radius="{fnum(self.dims[0])}"/>'


class Link:
    def __init__(self, name, mass, shapes, doc=""):
        self.name, self.mass, self.shapes, self.doc = name, mass, shapes, doc

    def collision_boxes(self):
        return [s for s in self.shapes if s.collision and s.kind == "box"]

    def inertial(self):
        """(mass, com, 3x3 inertia about com in link axes)."""
        parts = [s for s in self.shapes if s.inertial]
        vol = sum(s.volume() for s in parts)
        com = (0.0, 0.0, 0.0)
        for s in parts:
            com = vadd(com, vscale(s.xyz, s.volume() / vol))
        inertia = [[0.0] * 3 for _ in range(3)]
        for s in parts:
            m = self.mass * s.volume() / vol
            d = vsub(s.xyz, com)
            diag = s.inertia_diag(m)
            for i in range(3):
                inertia[i][i] += diag[i]
                for j in range(3):
                    inertia[i][j] += m * ((vdot(d, d) if i == j else 0.0) - d[i] * d[j])
        return self.mass, com, inertia


class Joint:
    def __init__(self, name, parent, child, xyz, axis=None, lower=0.0, upper=0.0, effort=0.0,
                 velocity=0.0, doc="", jtype="revolute"):
        self.name, self.parent, self.child, self.xyz = name, parent, child, tuple(xyz)
        self.axis, self.lower, self.upper = axis, lower, upper
        self.effort, self.velocity, self.doc, self.type = effort, velocity, doc, jtype


class Model:
    def __init__(self, name, root, materials, header):
        self.name, self.root, self.materials, self.header = name, root, materials, header
        self.links = {}
        self.link_order = []
        self.joints = []

    def add_link(self, link):
        assert link.name not in self.links, link.name
        self.links[link.name] = link
        self.link_order.append(link.name)

    def add_joint(self, joint):
        assert joint.parent in self.links and joint.child in self.links, joint.name
        assert all(j.child != joint.child for j in self.joints), joint.child
        self.joints.append(joint)

    def total_mass(self):
        return sum(l.mass for l in self.links.values())

    # --- URDF writer -----------------------------------------------------------------------------
    def urdf(self):
        out = ['<?xml version="1.0"?>']
        out += ["<!-- " + line + " -->" if line else "" for line in self.header]
        out.append(f'<robot name="{self.name}">')
        out.append("")
        for name, rgba in self.materials:
            out.append(f'  <material name="{name}"><color rgba="{fvec(rgba, 3)}"/></material>')
        out.append("")
        out += self._link_xml(self.links[self.root])
        for j in self.joints:
            out.append("")
            out += self._joint_xml(j)
            out += self._link_xml(self.links[j.child])
        out.append("")
        out.append("</robot>")
        return "\n".join(out) + "\n"

    def _link_xml(self, link):
        m, com, inertia = link.inertial()
        check_inertia(link.name, m, inertia)
        out = []
        if link.doc:
            out.append(f"  <!-- {link.doc} -->")
        out.append(f'  <link name="{link.name}">')
        out.append("    <inertial>")
        out.append(f'      <origin xyz="{fvec(com)}" rpy="0 0 0"/>')
        out.append(f'      <mass value="{fnum(m, 4)}"/>')
        out.append('      <inertia ixx="%s" ixy="%s" ixz="%s" iyy="%s" iyz="%s" izz="%s"/>' % (
            fsci(inertia[0][0]), fsci(inertia[0][1]), fsci(inertia[0][2]),
            fsci(inertia[1][1]), fsci(inertia[1][2]), fsci(inertia[2][2])))
        out.append("    </inertial>")
        for s in link.shapes:
            if not s.visual:
                continue
            out.append("    <visual>")
            out.append(f'      <origin xyz="{fvec(s.xyz)}" rpy="{fvec(s.rpy(), 9)}"/>')
            out.append(f"      <geometry>{s.geometry_xml()}</geometry>")
            out.append(f'      <material name="{s.material}"/>')
            out.append("    </visual>")
        for s in link.shapes:
            if not s.collision:
                continue
            name_attr = f' name="{s.name}"' if s.name else ""
            out.append(f"    <collision{name_attr}>")
            out.append(f'      <origin xyz="{fvec(s.xyz)}" rpy="{fvec(s.rpy(), 9)}"/>')
            out.append(f"      <geometry>{s.geometry_xml()}</geometry>")
            out.append("    </collision>")
        out.append("  </link>")
        return out

    def _joint_xml(self, j):
        out = []
        if j.doc:
            out.append(f"  <!-- {j.name}: {j.doc} -->")
        out.append(f'  <joint name="{j.name}" type="{j.type}">')
        out.append(f'    <parent link="{j.parent}"/>')
        out.append(f'    <child link="{j.child}"/>')
        out.append(f'    <origin xyz="{fvec(j.xyz)}" rpy="0 0 0"/>')
        if j.type == "revolute":
            out.append(f'    <axis xyz="{fvec(j.axis)}"/>')
            out.append(f'    <limit lower="{fnum(j.lower, 4)}" upper="{fnum(j.upper, 4)}" '
                       f'effort="{fnum(j.effort, 3)}" velocity="{fnum(j.velocity, 3)}"/>')
        out.append("  </joint>")
        return out


def check_inertia(name, m, I):
    assert m > 0, name
    for i in range(3):
        for j in range(3):
            assert abs(I[i][j] - I[j][i]) < 1e-15, name
    d1 = I[0][0]
    d2 = I[0][0] * I[1][1] - I[0][1] * I[1][0]
    d3 = (I[0][0] * (I[1][1] * I[2][2] - I[1][2] * I[2][1])
          - I[0][1] * (I[1][0] * I[2][2] - I[1][2] * I[2][0])
          + I[0][2] * (I[1][0] * I[2][1] - I[1][1] * I[2][0]))
    assert d1 > 0 and d2 > 0 and d3 > 0, f"{name}: inertia not positive definite"
    a, b, c = I[0][0], I[1][1], I[2][2]
    assert a + b >= c and b + c >= a and a + c >= b, f"{name}: triangle inequality"


# ------------------------------------------------------------------------------------------------
# The humanoid. All dimensions in one place.

H = dict(
    waist_height=0.93,        # waist origin above the soles at the zero configuration
    hip_y=0.085,              # lateral offset of the hip yaw axis from the waist origin
    hip_yaw_drop=0.06,        # waist origin -> hip yaw joint (down)
    hip_roll_drop=0.08,       # hip yaw joint -> hip roll/pitch joints (down)
    thigh=0.31,               # hip pitch -> knee
    shank=0.38,               # knee -> ankle
    ankle_height=0.10,        # ankle -> sole
    chest_yaw_up=0.12,        # waist -> chest yaw
    chest_pitch_up=0.02,      # chest yaw -> chest pitch
    shoulder=(0.0, 0.21, 0.24),  # chest pitch -> shoulder joints (left; y mirrored for right)
    upper_arm=0.28,           # shoulder -> elbow
    forearm=0.22,             # elbow -> wrist
    neck_yaw_up=0.29,         # chest pitch -> neck yaw
    neck_pitch_up=0.04,       # neck yaw -> neck pitch
    finger_hinge=(0.06, 0.0, -0.035),  # hand frame -> gripper joint
    foot_box=(0.22, 0.13, 0.03),
    foot_box_center=(0.02, 0.0, -0.085),   # ankle frame; bottom face at -0.10 = sole
)

# name, axis, lower, upper, effort (N m), velocity (rad/s), positive direction. For the roll joints the
# left range is given; the right one is mirrored. Same axis on both sides (a positive roll always
# moves toward +y).
LEG_JOINTS = [
    ("hip_y", "z", -0.7, 0.7, 120, 5.0,
     "yaw about +z; positive turns the leg so that the toes point toward +y (left)"),
    ("hip_r", "x", -0.4, 0.7, 200, 5.0,
     "roll about +x; positive swings the leg toward +y (abduction of the left leg, adduction of the right)"),
    ("hip_p", "y", -2.2, 0.6, 250, 5.0,
     "pitch about +y; negative swings the thigh forward and up (flexion, -1.57 = thigh horizontal), "
     "positive backward"),
    ("knee_p", "y", 0.0, 2.5, 300, 5.0,
     "pitch about +y; positive bends the knee, the shank swings backward as in humans (0 = straight)"),
    ("ankle_p", "y", -1.25, 0.75, 180, 5.0,
     "pitch about +y; positive points the toes down (plantar flexion), negative lifts them"),
    ("ankle_r", "x", -0.5, 0.5, 120, 5.0,
     "roll about +x; positive lifts the sole's +y (left) edge"),
]
ARM_JOINTS = [
    ("shoulder_p", "y", -3.1, 1.0, 110, 4.0,
     "pitch about +y; negative raises the arm forward (-1.57 = arm horizontal in front), positive "
     "swings it backward"),
    ("shoulder_r", "x", -0.5, 2.6, 100, 4.0,
     "roll about +x; positive swings the arm toward +y (abduction of the left arm, adduction of the right)"),
    ("shoulder_y", "z", -1.6, 1.6, 80, 4.0,
     "yaw about the upper-arm axis (+z at zero); positive turns a bent forearm toward +y"),
    ("elbow_p", "y", -2.4, 0.0, 70, 4.0,
     "pitch about +y; NEGATIVE bends the elbow (forearm forward and up, -1.57 = forearm horizontal "
     "in front), 0 = straight"),
    ("wrist_y", "z", -1.6, 1.6, 30, 5.0,
     "yaw about the forearm axis (+z at zero); positive turns the palm normal from -x toward -y"),
    ("wrist_p", "y", -1.6, 1.6, 35, 5.0,
     "pitch about +y; positive swings the hand toward its palm side (-x), negative toward its back"),
    ("wrist_r", "x", -1.0, 1.0, 25, 5.0,
     "roll about +x; positive swings the hand toward +y"),
]
TORSO_JOINTS = [
    ("chest_y", "z", -0.8, 0.8, 150, 3.0, "yaw about +z; positive turns the torso to the left"),
    ("chest_p", "y", -0.2, 1.0, 200, 3.0, "pitch about +y; positive leans the torso forward"),
    ("neck_y", "z", -1.0, 1.0, 10, 4.0, "yaw about +z; positive turns the head to the left"),
    ("neck_p", "y", -0.5, 0.7, 10, 4.0, "pitch about +y; positive tilts the head forward (nod)"),
]
GRIPPER = ("gripper", "y", -1.0, 0.3, 10, 2.0,
           "pitch about +y; positive closes the finger toward the back (+x face) of the hand "
           "(0 = fingers parallel to the hand with a 2.75 cm gap, about 0.3 = touching), negative opens")

MASSES = dict(
    waist=8.0, hip_y_link=0.9, hip_r_link=1.1, hip_p_link=4.2, knee_p_link=2.7, ankle_p_link=0.5,
    foot=1.3, chest_y_link=1.5, chest_p_link=13.5, neck_y_link=0.3, neck_p_link=2.4,
    shoulder_p_link=0.9, shoulder_r_link=0.8, shoulder_y_link=1.6, elbow_p_link=1.1,
    wrist_y_link=0.3, wrist_p_link=0.3, hand=0.5, finger=0.12,
)

B, D, A = "body_light", "joint_dark", "accent_blue"


def box(dims, xyz, material=B, collision=True, visual=True, inertial=True, name=None):
    return Shape("box", dims, xyz, material=material, collision=collision, visual=visual,
                 inertial=inertial, name=name)


def cyl(r, length, xyz, axis, material=D, inertial=True):
    return Shape("cylinder", (r, length), xyz, axis=axis, material=material, inertial=inertial)


def deco(dims, xyz, material=A):
    """Visual-only box (no mass, no collision)."""
    return Shape("box", dims, xyz, material=material, inertial=False)


def find_spec(table, short):
    for row in table:
        if row[0] == short:
            return row
    raise KeyError(short)


def build_humanoid():
    h = H
    header = [
        "humanoid: stanceplan's own HRP-2-class humanoid (floating base, root link waist).",
        "Generated by scripts/generate_assets.py - do not edit by hand; change the script instead.",
        f"waist height standing: {fnum(h['waist_height'])} m (waist origin above the sole plane at the zero configuration)",
        "Frames: x forward, y left, z up. All joint origins have rpy = 0: at the zero configuration every",
        "link frame is parallel to the waist frame; the robot stands straight, arms hanging, palms (the",
        "hands' -x faces) facing backward, feet flat with the soles at z = waist z - waist height.",
        "Inertials: uniform solids (boxes / cylinders) per link. Collision: boxes only.",
    ]
    m = Model("humanoid", "waist", ROBOT_MATERIALS, header)

    # --- waist (pelvis) ---------------------------------------------------------------------------
    m.add_link(Link("waist", MASSES["waist"], [
        box((0.16, 0.24, 0.12), (0.0, 0.0, 0.01), name="pelvis"),
        deco((0.165, 0.245, 0.02), (0.0, 0.0, 0.05)),
    ], "pelvis; the floating base"))

    # --- legs -----------------------------------------------------------------------------------
    hy = h["hip_y"]
    ankle = -(h["ankle_height"])
    for side, s in (("l", 1.0), ("r", -1.0)):
        chain = [
            (f"{side}_hip_y_link", MASSES["hip_y_link"], "waist", (0.0, s * hy, -h["hip_yaw_drop"]),
             [cyl(0.04, 0.06, (0.0, 0.0, -0.035), "z")], "hip yaw actuator"),
            (f"{side}_hip_r_link", MASSES["hip_r_link"], f"{side}_hip_y_link", (0.0, 0.0, -h["hip_roll_drop"]),
             [cyl(0.045, 0.10, (0.0, 0.0, 0.0), "x")], "hip roll actuator"),
            (f"{side}_hip_p_link", MASSES["hip_p_link"], f"{side}_hip_r_link", (0.0, 0.0, 0.0),
             [box((0.10, 0.09, 0.25), (0.0, 0.0, -0.155), name=f"{side}_thigh"),
              cyl(0.045, 0.09, (0.0, 0.0, 0.0), "y"),
              deco((0.005, 0.04, 0.18), (0.0525, 0.0, -0.155))], "thigh"),
            (f"{side}_knee_p_link", MASSES["knee_p_link"], f"{side}_hip_p_link", (0.0, 0.0, -h["thigh"]),
             [box((0.09, 0.08, 0.30), (0.0, 0.0, -0.13), name=f"{side}_shank"),
              cyl(0.045, 0.085, (0.0, 0.0, 0.0), "y")], "shank"),
            (f"{side}_ankle_p_link", MASSES["ankle_p_link"], f"{side}_knee_p_link", (0.0, 0.0, -h["shank"]),
             [cyl(0.035, 0.07, (0.0, 0.0, 0.0), "y")], "ankle pitch actuator"),
            (f"{side}_foot", MASSES["foot"], f"{side}_ankle_p_link", (0.0, 0.0, 0.0),
             [box(h["foot_box"], h["foot_box_center"], name=f"{side}_sole_plate"),
              box((0.08, 0.07, 0.04), (0.0, 0.0, -0.05), material=D, name=f"{side}_ankle_block"),
              cyl(0.03, 0.08, (0.0, 0.0, 0.0), "x")], "foot; box 0 is the sole plate (bottom face = sole)"),
        ]
        assert abs(h["foot_box_center"][2] - h["foot_box"][2] / 2.0 - ankle) < 1e-12
        for (lname, mass, parent, xyz, shapes, doc), spec in zip(chain, LEG_JOINTS):
            short, axis, lo, up, eff, vel, jdoc = spec
            if side == "r" and short == "hip_r":
                lo, up = -up, -lo
            m.add_link(Link(lname, mass, shapes, doc))
            m.add_joint(Joint(f"{side}_{short}", parent, lname, xyz, AXES[axis], lo, up, eff, vel, jdoc))

    # --- torso and head ---------------------------------------------------------------------------
    torso = [
        ("chest_y_link", "waist", (0.0, 0.0, h["chest_yaw_up"]),
         [cyl(0.06, 0.06, (0.0, 0.0, -0.01), "z")], "chest yaw actuator"),
        ("chest_p_link", "chest_y_link", (0.0, 0.0, h["chest_pitch_up"]),
         [box((0.20, 0.26, 0.26), (0.0, 0.0, 0.15), name="chest"),
          cyl(0.04, 0.14, (0.0, 0.0, 0.0), "y"),
          deco((0.01, 0.18, 0.14), (0.105, 0.0, 0.17))], "chest (torso); carries the arms and the neck"),
        ("neck_y_link", "chest_p_link", (0.0, 0.0, h["neck_yaw_up"]),
         [cyl(0.03, 0.04, (0.0, 0.0, 0.02), "z")], "neck yaw actuator"),
        ("neck_p_link", "neck_y_link", (0.0, 0.0, h["neck_pitch_up"]),
         [box((0.17, 0.15, 0.14), (0.01, 0.0, 0.08), name="head"),
          cyl(0.025, 0.07, (0.0, 0.0, 0.0), "y"),
          deco((0.01, 0.12, 0.04), (0.1, 0.0, 0.09), material=D)], "head"),
    ]
    for (lname, parent, xyz, shapes, doc), spec in zip(torso, TORSO_JOINTS):
        short, axis, lo, up, eff, vel, jdoc = spec
        m.add_link(Link(lname, MASSES[lname], shapes, doc))
        m.add_joint(Joint(short, parent, lname, xyz, AXES[axis], lo, up, eff, vel, jdoc))

    # --- arms -------------------------------------------------------------------------------------
    sx, sy, sz = h["shoulder"]
    for side, s in (("l", 1.0), ("r", -1.0)):
        chain = [
            (f"{side}_shoulder_p_link", "shoulder_p_link", "chest_p_link", (sx, s * sy, sz),
             [cyl(0.045, 0.06, (0.0, 0.0, 0.0), "y")], "shoulder pitch actuator"),
            (f"{side}_shoulder_r_link", "shoulder_r_link", f"{side}_shoulder_p_link", (0.0, 0.0, 0.0),
             [cyl(0.04, 0.09, (0.0, 0.0, 0.0), "x")], "shoulder roll actuator"),
            (f"{side}_shoulder_y_link", "shoulder_y_link", f"{side}_shoulder_r_link", (0.0, 0.0, 0.0),
             [box((0.07, 0.07, 0.21), (0.0, 0.0, -0.145), name=f"{side}_upper_arm")], "upper arm"),
            (f"{side}_elbow_p_link", "elbow_p_link", f"{side}_shoulder_y_link", (0.0, 0.0, -h["upper_arm"]),
             [box((0.065, 0.065, 0.20), (0.0, 0.0, -0.08), name=f"{side}_forearm"),
              cyl(0.035, 0.075, (0.0, 0.0, 0.0), "y"),
              deco((0.068, 0.068, 0.02), (0.0, 0.0, -0.16))], "forearm"),
            (f"{side}_wrist_y_link", "wrist_y_link", f"{side}_elbow_p_link", (0.0, 0.0, -h["forearm"]),
             [cyl(0.03, 0.03, (0.0, 0.0, 0.015), "z")], "wrist yaw actuator"),
            (f"{side}_wrist_p_link", "wrist_p_link", f"{side}_wrist_y_link", (0.0, 0.0, 0.0),
             [cyl(0.025, 0.06, (0.0, 0.0, 0.0), "y")], "wrist pitch actuator"),
            (f"{side}_hand", "hand", f"{side}_wrist_p_link", (0.0, 0.0, 0.0),
             [box((0.05, 0.08, 0.10), (0.0, 0.0, -0.08), material=D, name=f"{side}_palm_block"),
              cyl(0.022, 0.05, (0.0, 0.0, 0.0), "x")], "hand; the palm is the -x face of its box"),
        ]
        for (lname, mkey, parent, xyz, shapes, doc), spec in zip(chain, ARM_JOINTS):
            short, axis, lo, up, eff, vel, jdoc = spec
            if side == "r" and short == "shoulder_r":
                lo, up = -up, -lo
            m.add_link(Link(lname, MASSES[mkey], shapes, doc))
            m.add_joint(Joint(f"{side}_{short}", parent, lname, xyz, AXES[axis], lo, up, eff, vel, jdoc))
        short, axis, lo, up, eff, vel, jdoc = GRIPPER
        m.add_link(Link(f"{side}_finger", MASSES["finger"],
                        [box((0.015, 0.06, 0.08), (0.0, 0.0, -0.045), material=A, name=f"{side}_finger")],
                        "gripper finger, closes against the back (+x face) of the hand"))
        m.add_joint(Joint(f"{side}_{short}", f"{side}_hand", f"{side}_finger", h["finger_hinge"], AXES[axis],
                          lo, up, eff, vel, jdoc))
    return m


# ------------------------------------------------------------------------------------------------
# Surfaces


def box_of(model, link, index=0):
    return model.links[link].collision_boxes()[index]


def rect_on_face(model, name, link, face, ranges, x_axis, box_index=0):
    """A rectangle lying on face `face` ('+x', ...) of the link's collision box `box_index`.
    ranges: {axis letter: (lo, hi)} for the two in-plane link axes (None = the whole face)."""
    b = box_of(model, link, box_index)
    k = "xyz".index(face[1])
    sign = 1.0 if face[0] == "+" else -1.0
    half = b.half()
    normal = tuple(sign if i == k else 0.0 for i in range(3))
    plane = b.xyz[k] + sign * half[k]
    spans = []
    for i in range(3):
        if i == k:
            continue
        lo_face, hi_face = b.xyz[i] - half[i], b.xyz[i] + half[i]
        lo, hi = ranges.get("xyz"[i]) or (lo_face, hi_face)
        assert lo_face - 1e-12 <= lo < hi <= hi_face + 1e-12, f"{name}: outside the face"
        spans.append((i, lo, hi))
    (i0, a0, a1), (i1, b0, b1) = spans
    corners = []
    for u, v in ((a0, b0), (a1, b0), (a1, b1), (a0, b1)):
        p = [0.0, 0.0, 0.0]
        p[k], p[i0], p[i1] = plane, u, v
        corners.append(tuple(p))
    corners = ccw(corners, normal)
    return dict(name=name, link=link, normal=normal, vertices=corners, x_axis=x_axis)


def ccw(vertices, normal):
    """Order a convex polygon's vertices counter-clockwise about `normal` and check it."""
    c = vscale(tuple(map(sum, zip(*vertices))), 1.0 / len(vertices))
    u = vsub(vertices[0], c)
    v = vcross(normal, u)
    ordered = sorted(vertices, key=lambda p: math.atan2(vdot(vsub(p, c), v), vdot(vsub(p, c), u)))
    assert ccw_area(ordered, normal) > 0.0
    return ordered


def ccw_area(vertices, normal):
    """sum_i (v_i x v_i+1) . n / 2: positive when counter-clockwise about n."""
    total = 0.0
    n = len(vertices)
    for i in range(n):
        total += vdot(vcross(vertices[i], vertices[(i + 1) % n]), normal)
    return total / 2.0


def humanoid_surfaces(m):
    sur = []
    for side in ("l", "r"):
        sur.append(rect_on_face(m, f"{side}_sole", f"{side}_foot", "-z", {}, (1, 0, 0)))
    for side in ("l", "r"):
        sur.append(rect_on_face(m, f"{side}_palm", f"{side}_hand", "-x", {}, (0, 0, -1)))
    for side in ("l", "r"):   # most of the forearm's -x face: the underside when the forearm
        # is horizontal in front of the body (elbow_p = -1.57)
        sur.append(rect_on_face(m, f"{side}_forearm", f"{side}_elbow_p_link", "-x",
                                {"y": (-0.025, 0.025), "z": (-0.17, -0.02)}, (0, 0, -1)))
    for side in ("l", "r"):   # rear face of the thigh near the hip: on the seat when hip_p = -1.57
        sur.append(rect_on_face(m, f"{side}_thigh", f"{side}_hip_p_link", "-x",
                                {"y": (-0.035, 0.035), "z": (-0.13, -0.03)}, (0, 0, -1)))
    for side in ("l", "r"):   # front face of the shank just below the knee axis
        sur.append(rect_on_face(m, f"{side}_knee", f"{side}_knee_p_link", "+x",
                                {"y": (-0.03, 0.03), "z": (-0.10, 0.01)}, (0, 0, -1)))
    return sur


SURFACE_DOCS = {
    "sole": "bottom (-z) face of the foot's sole plate (collision box 0), whole face",
    "palm": "-x face of the hand box, whole face (faces backward at zero, down when the arm points forward)",
    "forearm": "-x face of the forearm box, most of it (z -0.17..-0.02 below the elbow): the underside "
               "when the forearm is horizontal in front of the body",
    "thigh": "-x (back) face of the thigh box near the hip (z -0.13..-0.03): on the seat when sitting",
    "knee": "+x (front) face of the shank box just below the knee (z -0.10..0.01)",
}


def surfaces_yaml(title, surfaces, generator="scripts/generate_assets.py"):
    out = [f"# {title}", f"# Generated by {generator} - do not edit by hand.",
           "format: stanceplan/surfaces@1", "surfaces:"]
    for s in surfaces:
        out.append(f"  - name: {s['name']}")
        out.append(f"    link: {s['link']}")
        if "point" in s:  # a point surface: a sphere of `radius` centred at `point`
            out.append(f"    point: {yvec(s['point'])}")
            out.append(f"    radius: {fnum(s['radius'])}")
        elif "box_face" in s:
            out.append(f"    box_face: \"{s['box_face']}\"")
            out.append(f"    box_index: {s.get('box_index', 0)}")
            if s.get("inset"):
                out.append(f"    inset: {fnum(s['inset'])}")
        else:
            out.append(f"    normal: {yvec(s['normal'])}")
            out.append("    vertices: [" + ", ".join(yvec(v) for v in s["vertices"]) + "]")
            out.append(f"    x_axis: {yvec(s['x_axis'])}")
    return "\n".join(out) + "\n"


# ------------------------------------------------------------------------------------------------
# Environments

FLOOR = dict(size=(8.0, 6.0, 0.05), center_xy=(1.5, 0.0))   # x -2.5..5.5, y -3..3, top at z = 0
DESK = dict(x=2.35, top=0.78, board=(0.70, 1.20, 0.03), leg=0.05, leg_inset=0.03)
CHAIR = dict(x=1.52, seat_top=0.42, seat=(0.45, 0.45, 0.04), leg=0.035, back=(0.03, 0.43),
             leg_inset_x=0.06)  # legs set back from the seat's front/back edges: room for heels under the seat
WALL = dict(x=0.60, size=(0.10, 3.0, 2.0))
DENSITY = dict(floor=1000.0, wood=600.0, wall=1500.0)


def env_box_link(name, boxes, density, doc):
    """boxes: list of (dims, xyz, material, name); mass from the density."""
    shapes = [Shape("box", d, c, material=mat, collision=True, name=n) for d, c, mat, n in boxes]
    mass = round(density * sum(s.volume() for s in shapes), 3)
    return Link(name, mass, shapes, doc)


def floor_link():
    sx, sy, sz = FLOOR["size"]
    cx, cy = FLOOR["center_xy"]
    return env_box_link("floor", [((sx, sy, sz), (cx, cy, -sz / 2.0), "floor_light", "floor")],
                        DENSITY["floor"], f"floor slab {fnum(sx)} x {fnum(sy)} x {fnum(sz)} m, top face at z = 0")


def env_header(name, lines):
    return [f"{name}: stanceplan environment (fixed, root link floor).",
            "Generated by scripts/generate_assets.py - do not edit by hand; change the script instead.",
            "Frames: x forward (the humanoid starts at the origin facing +x), y left, z up; floor top at z = 0."
            ] + lines


def build_desk_room():
    m = Model("desk_room", "floor", ENV_MATERIALS, env_header("desk_room", [
        f"desk: top face at z = {fnum(DESK['top'])} m, board {fnum(DESK['board'][0])} (x) x {fnum(DESK['board'][1])} (y) m, "
        f"centre x = {fnum(DESK['x'])} m (near edge at x = {fnum(DESK['x'] - DESK['board'][0] / 2)} m)",
        f"chair: seat top at z = {fnum(CHAIR['seat_top'])} m, seat {fnum(CHAIR['seat'][0])} x {fnum(CHAIR['seat'][1])} m, "
        f"centre x = {fnum(CHAIR['x'])} m, facing +x (the desk); backrest at its -x edge",
    ]))
    m.add_link(floor_link())
    # desk: box 0 = top board, then four legs
    bx, by, bt = DESK["board"]
    top, leg, ins = DESK["top"], DESK["leg"], DESK["leg_inset"]
    leg_h = top - bt
    boxes = [((bx, by, bt), (0.0, 0.0, top - bt / 2.0), "wood", "desk_top")]
    for i, (px, py) in enumerate(((1, 1), (1, -1), (-1, -1), (-1, 1))):
        boxes.append(((leg, leg, leg_h), (px * (bx / 2 - ins - leg / 2), py * (by / 2 - ins - leg / 2), leg_h / 2.0),
                      "wood_dark", f"desk_leg_{i}"))
    m.add_link(env_box_link("desk", boxes, DENSITY["wood"], "desk; collision box 0 is the top board"))
    m.add_joint(Joint("floor_to_desk", "floor", "desk", (DESK["x"], 0.0, 0.0), jtype="fixed"))
    # chair: box 0 = seat, box 1 = backrest, then four legs
    cx, cy, ct = CHAIR["seat"]
    st, leg = CHAIR["seat_top"], CHAIR["leg"]
    bth, bh = CHAIR["back"]
    leg_h = st - ct
    boxes = [((cx, cy, ct), (0.0, 0.0, st - ct / 2.0), "wood", "chair_seat"),
             ((bth, cy, bh), (-cx / 2 + bth / 2, 0.0, st + bh / 2.0), "wood", "chair_back")]
    for i, (px, py) in enumerate(((1, 1), (1, -1), (-1, -1), (-1, 1))):
        boxes.append(((leg, leg, leg_h), (px * (cx / 2 - CHAIR["leg_inset_x"] - leg / 2), py * (cy / 2 - leg / 2), leg_h / 2.0),
                      "wood_dark", f"chair_leg_{i}"))
    m.add_link(env_box_link("chair", boxes, DENSITY["wood"],
                            "chair facing +x; collision box 0 is the seat, box 1 the backrest"))
    m.add_joint(Joint("floor_to_chair", "floor", "chair", (CHAIR["x"], 0.0, 0.0), jtype="fixed"))
    surfaces = [
        dict(name="floor", link="floor", box_face="+z", box_index=0),
        dict(name="desk_top", link="desk", box_face="+z", box_index=0),
        dict(name="chair_seat", link="chair", box_face="+z", box_index=0),
        dict(name="chair_back", link="chair", box_face="+x", box_index=1),
    ]
    return m, surfaces


def build_flat_ground():
    m = Model("flat_ground", "floor", ENV_MATERIALS, env_header("flat_ground", []))
    m.add_link(floor_link())
    return m, [dict(name="floor", link="floor", box_face="+z", box_index=0)]


def build_wall():
    m = Model("wall", "floor", ENV_MATERIALS, env_header("wall", [
        f"wall: vertical, its -x face at x = {fnum(WALL['x'])} m, {fnum(WALL['size'][1])} m wide, "
        f"{fnum(WALL['size'][2])} m high"]))
    m.add_link(floor_link())
    t, w, hgt = WALL["size"]
    m.add_link(env_box_link("wall", [((t, w, hgt), (t / 2.0, 0.0, hgt / 2.0), "wall_paint", "wall")],
                            DENSITY["wall"], "wall slab; its -x face (x = 0.6 m in the world) faces the robot"))
    m.add_joint(Joint("floor_to_wall", "floor", "wall", (WALL["x"], 0.0, 0.0), jtype="fixed"))
    return m, [dict(name="floor", link="floor", box_face="+z", box_index=0),
               dict(name="wall", link="wall", box_face="-x", box_index=0)]


# ------------------------------------------------------------------------------------------------
# Checks: forward kinematics, box clearances, a seated posture at the desk


def fk(model, q, base_p=(0.0, 0.0, 0.0)):
    """World pose (R, p) of every link; the root at base_p with identity orientation."""
    poses = {model.root: (IDENTITY, tuple(base_p))}
    for j in model.joints:
        R, p = poses[j.parent]
        pc = vadd(p, mvec(R, j.xyz))
        Rc = mmul(R, axis_angle(j.axis, q.get(j.name, 0.0))) if j.type == "revolute" else R
        poses[j.child] = (Rc, pc)
    return poses


def world_boxes(model, poses, tag):
    """[(tag, link, box index, centre, R, half extents)] of every collision box."""
    out = []
    for name in model.link_order:
        R, p = poses[name]
        for i, b in enumerate(model.links[name].collision_boxes()):
            out.append((tag, name, i, vadd(p, mvec(R, b.xyz)), R, b.half()))
    return out


def separated(A, B, margin):
    """SAT test of two oriented boxes, each inflated by `margin` along its own axes."""
    ca, Ra, ha = A[3], A[4], tuple(x + margin for x in A[5])
    cb, Rb, hb = B[3], B[4], tuple(x + margin for x in B[5])
    if min(ha) <= 0 or min(hb) <= 0:
        return True
    ax = [mcol(Ra, i) for i in range(3)]
    bx = [mcol(Rb, i) for i in range(3)]
    axes = ax + bx
    for a in ax:
        for b in bx:
            c = vcross(a, b)
            if vdot(c, c) > 1e-12:
                axes.append(c)
    d = vsub(cb, ca)
    for L in axes:
        ra = sum(ha[i] * abs(vdot(ax[i], L)) for i in range(3))
        rb = sum(hb[i] * abs(vdot(bx[i], L)) for i in range(3))
        if abs(vdot(d, L)) > ra + rb + 1e-12:
            return True
    return False


def clearance(A, B):
    """Distance between two boxes: exact when both are axis-aligned, otherwise a lower bound
    (twice the largest inflation margin that keeps them separated; negative = penetration)."""
    if A[4] == IDENTITY and B[4] == IDENTITY:
        gaps = [abs(A[3][i] - B[3][i]) - A[5][i] - B[5][i] for i in range(3)]
        pos = [g for g in gaps if g > 0]
        return math.sqrt(sum(g * g for g in pos)) if pos else max(gaps)
    lo, hi = -min(min(A[5]), min(B[5])), 0.5
    if separated(A, B, hi):
        return 2 * hi
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        if separated(A, B, mid):
            lo = mid
        else:
            hi = mid
    return 2 * lo


def adjacent_pairs(model):
    return {frozenset((j.parent, j.child)) for j in model.joints}


def self_clearances(model, poses):
    boxes = world_boxes(model, poses, "robot")
    adj = adjacent_pairs(model)
    res = []
    for i in range(len(boxes)):
        for k in range(i + 1, len(boxes)):
            a, b = boxes[i], boxes[k]
            if a[1] == b[1] or frozenset((a[1], b[1])) in adj:
                continue
            res.append((clearance(a, b), a[1], b[1]))
    return sorted(res)


def surface_world(surf, poses):
    R, p = poses[surf["link"]]
    return [vadd(p, mvec(R, v)) for v in surf["vertices"]], mvec(R, surf["normal"])


def env_face(env, link, box_index, face):
    """World polygon (axis-aligned rectangle) of an environment box face: (plane value, lo, hi)."""
    poses = fk(env, {})
    b = world_boxes(env, poses, "env")
    b = [x for x in b if x[1] == link and x[2] == box_index][0]
    k = "xyz".index(face[1])
    sign = 1.0 if face[0] == "+" else -1.0
    c, h = b[3], b[5]
    lo = tuple(c[i] - h[i] for i in range(3))
    hi = tuple(c[i] + h[i] for i in range(3))
    return c[k] + sign * h[k], lo, hi


def seated_posture(m, surfaces, env):
    """Search a simple symmetric seated posture: thighs on the seat, feet flat on the floor, forearms
    horizontal on the desk. Returns the best (by clearance) configuration and its report."""
    h = H
    seat_z, seat_lo, seat_hi = env_face(env, "chair", 0, "+z")
    desk_z, desk_lo, desk_hi = env_face(env, "desk", 0, "+z")
    thigh_half = box_of(m, "l_hip_p_link").half()[0]
    fore_half = box_of(m, "l_elbow_p_link").half()[0]
    hip_z = seat_z + thigh_half                   # thigh horizontal, back face on the seat
    drop = hip_z - h["ankle_height"]              # knee (at hip height) -> ankle, vertical part
    tilt = math.acos(drop / h["shank"])           # shank tilted with the feet slightly back
    waist_z = hip_z + h["hip_yaw_drop"] + h["hip_roll_drop"]
    surf = {s["name"]: s for s in surfaces}
    env_poses = fk(env, {})
    env_boxes = world_boxes(env, env_poses, "env")
    touching = {("l_hip_p_link", "chair", 0), ("r_hip_p_link", "chair", 0),
                ("l_elbow_p_link", "desk", 0), ("r_elbow_p_link", "desk", 0),
                ("l_foot", "floor", 0), ("r_foot", "floor", 0)}
    best = None
    for ci in range(0, 21):
        lean = 0.05 * ci
        q = {}
        for side in ("l", "r"):
            q[f"{side}_hip_p"] = -math.pi / 2
            q[f"{side}_knee_p"] = math.pi / 2 + tilt
            q[f"{side}_ankle_p"] = -tilt
        q["chest_p"] = lean
        poses0 = fk(m, q, (0.0, 0.0, waist_z))
        sh_z = poses0["l_shoulder_p_link"][1][2]
        elbow_z = desk_z + fore_half
        if not 0 < sh_z - elbow_z < h["upper_arm"]:
            continue
        arm_abs = -math.acos((sh_z - elbow_z) / h["upper_arm"])   # upper-arm pitch in the world
        for side in ("l", "r"):
            q[f"{side}_shoulder_p"] = arm_abs - lean
            q[f"{side}_elbow_p"] = -math.pi / 2 - arm_abs
            q[f"{side}_wrist_p"] = -0.5          # lift the hand off the desk
        if q["l_elbow_p"] < -2.4 or q["l_elbow_p"] > 0:
            continue
        for xi in range(0, 81):
            hx = 1.30 + 0.005 * xi
            poses = fk(m, q, (hx, 0.0, waist_z))
            margin = 1.0
            ok = True
            for name, (z, lo, hi) in (("l_thigh", (seat_z, seat_lo, seat_hi)),
                                      ("r_thigh", (seat_z, seat_lo, seat_hi)),
                                      ("l_forearm", (desk_z, desk_lo, desk_hi)),
                                      ("r_forearm", (desk_z, desk_lo, desk_hi)),
                                      ("l_sole", (0.0, (-9, -9, 0), (9, 9, 0))),
                                      ("r_sole", (0.0, (-9, -9, 0), (9, 9, 0)))):
                verts, _ = surface_world(surf[name], poses)
                for v in verts:
                    if abs(v[2] - z) > 1e-9:
                        ok = False
                    margin = min(margin, v[0] - lo[0], hi[0] - v[0], v[1] - lo[1], hi[1] - v[1])
            if not ok or margin < 0.0:
                continue
            rb = world_boxes(m, poses, "robot")
            env_min = 1.0
            for a in rb:
                for b in env_boxes:
                    if (a[1], b[1], b[2]) in touching:
                        continue
                    if separated(a, b, 0.0):
                        # cheap bound first; exact value only near contact
                        if separated(a, b, 0.05):
                            continue
                        env_min = min(env_min, clearance(a, b))
                    else:
                        env_min = min(env_min, clearance(a, b))
            score = min(margin, env_min)
            # the least forward lean that keeps 2 cm everywhere; otherwise the best score
            key = (1, -lean, score) if score >= 0.02 else (0, score, -lean)
            if best is None or key > best[0]:
                best = (key, dict(q), hx, waist_z, lean, margin, env_min, poses)
    return best


def report_humanoid(m, surfaces, env, verbose):
    """Check lines for the README; `verbose` receives the closest box pairs."""
    lines = []
    n_rev = sum(1 for j in m.joints if j.type == "revolute")
    lines.append(f"humanoid: {n_rev} revolute joints, {len(m.links)} links, mass {m.total_mass():.2f} kg")
    poses = fk(m, {}, (0.0, 0.0, H["waist_height"]))
    boxes = world_boxes(m, poses, "robot")
    zmin = min(b[3][2] - b[5][2] for b in boxes)
    zmax = max(b[3][2] + b[5][2] for b in boxes)
    sole_z = min(surface_world(s, poses)[0][0][2] for s in surfaces if s["name"].endswith("_sole"))
    assert abs(sole_z) < 1e-9, sole_z
    assert abs(zmin) < 1e-9, zmin
    lines.append(f"  zero configuration, waist at z = {H['waist_height']}: soles at z = {fnum(sole_z)}, "
                 f"top of head at z = {fnum(zmax)} -> height {fnum(zmax - sole_z)} m")
    # centre of mass at zero configuration
    com = (0.0, 0.0, 0.0)
    for name, link in m.links.items():
        mass, c, _ = link.inertial()
        R, p = poses[name]
        com = vadd(com, vscale(vadd(p, mvec(R, c)), mass))
    com = vscale(com, 1.0 / m.total_mass())
    lines.append(f"  centre of mass at zero configuration: ({com[0]:.3f}, {com[1]:.3f}, {com[2]:.3f}) m")
    sc = self_clearances(m, poses)
    lines.append(f"  min clearance between collision boxes of non-adjacent links (zero config): "
                 f"{sc[0][0]:.3f} m ({sc[0][1]} / {sc[0][2]})")
    assert sc[0][0] > 0.02, sc[0]
    for d, a, b in sc[:15]:
        verbose.append(f"    {d:.3f}  {a} / {b}")
    best = seated_posture(m, surfaces, env)
    if best is None:
        lines.append("  seated posture at the desk: NOT FOUND")
        return lines, None
    _, q, hx, wz, lean, margin, env_min, sposes = best
    sc = self_clearances(m, sposes)
    lines.append(f"  seated posture at the desk (waist at x = {hx:.3f}, z = {wz:.3f}, chest_p = {lean:.2f}): "
                 f"surfaces inside their supports by >= {margin:.3f} m, min clearance to the environment "
                 f"(contact pairs excluded) >= {env_min:.3f} m, self >= {sc[0][0]:.3f} m ({sc[0][1]} / {sc[0][2]})")
    qs = ", ".join(f"{k} {q[k]:.3f}" for k in sorted(q) if k.startswith("l_") or not k[1] == "_")
    lines.append(f"    joints (left side; right identical): {qs}")
    return lines, best


def report_standing_gap(m, env):
    """Can the robot stand straight between the chair's seat and the desk? (hands and fingers
    excluded: at the zero configuration they hang at the height of the desk's board)"""
    env_boxes = world_boxes(env, fk(env, {}), "env")
    good = []
    for xi in range(0, 61):
        hx = 1.60 + 0.005 * xi
        rb = world_boxes(m, fk(m, {}, (hx, 0.0, H["waist_height"])), "robot")
        rb = [b for b in rb if not b[1].endswith(("_hand", "_finger"))]
        dmin = min(clearance(a, b) for a in rb for b in env_boxes if b[1] != "floor")
        if dmin > 0.0:
            good.append((hx, dmin))
    if not good:
        return ["  standing straight between the chair and the desk: impossible"]
    best = max(good, key=lambda g: g[1])
    return [f"  standing straight between the chair and the desk (hands excluded): waist x in "
            f"[{good[0][0]:.3f}, {good[-1][0]:.3f}], best clearance {best[1]:.3f} m at x = {best[0]:.3f}"]


# ------------------------------------------------------------------------------------------------
# README


def joint_table(m):
    rows = ["| joint | parent -> child | axis | range (rad) | effort (N m) | velocity (rad/s) |",
            "|---|---|---|---|---|---|"]
    for j in m.joints:
        ax = "xyz"[[round(abs(c)) for c in j.axis].index(1)]
        rows.append(f"| `{j.name}` | {j.parent} -> {j.child} | {ax} | [{fnum(j.lower, 3)}, {fnum(j.upper, 3)}] "
                    f"| {fnum(j.effort)} | {fnum(j.velocity)} |")
    return rows


def readme(m, hum_surfaces, envs, report):
    h = H
    lines = [
        "# assets: stanceplan's own models",
        "",
        "Every file under `robots/humanoid/` and `environments/` is written by",
        "`scripts/generate_assets.py` (Python 3, standard library only). Do not edit them by hand: change",
        "the script and run `python3 scripts/generate_assets.py` (the output is deterministic; the script also",
        "prints the checks below; `--check` lists the closest collision-box pairs). Nothing here is copied",
        "from another model.",
        "",
        "## Conventions",
        "- World and every model: x forward, y left, z up; metres, kilograms, radians, N m.",
        "- Collision geometry: boxes only (no meshes, no capsules). Visuals: boxes and cylinders with the",
        "  named materials `body_light`, `joint_dark`, `accent_blue` (robot) and `floor_light`, `wood`,",
        "  `wood_dark`, `wall_paint` (environments).",
        "- Inertials: every link has a mass, a centre of mass and the inertia tensor of uniform-density",
        "  solids (its boxes and cylinders, combined with the parallel-axis theorem); all positive definite.",
        "- Surface files use the format `stanceplan/surfaces@1` (see `planner/contact/surface_file.h`).",
        "  Robot surfaces give explicit vertices (counter-clockwise about the outward normal, lying on a face",
        "  of the link's collision box); environment surfaces use `box_face` (`box_index` counts the link's",
        "  collision boxes in file order).",
        "",
        "## robots/humanoid: `humanoid.urdf`, `humanoid.surfaces.yaml`",
        f"An HRP-2-class humanoid: height {report['height']:.2f} m, mass {m.total_mass():.2f} kg, "
        f"{report['joints']} revolute joints, {len(m.links)} links, no fixed joints.",
        "Floating base: the root link is `waist` (no world link, no floating joint in the file).",
        "",
        f"- Zero configuration: standing straight, arms hanging along the body, palms (the hands' -x faces)",
        f"  facing backward, feet flat. With the waist origin at z = **{fnum(h['waist_height'])} m** the soles are",
        "  at z = 0. Every joint origin has rpy = 0, so all link frames are parallel to the waist frame there.",
        f"- Leg: hip yaw {fnum(h['hip_yaw_drop'])} m below the waist and {fnum(h['hip_y'])} m to the side; hip roll and pitch",
        f"  {fnum(h['hip_roll_drop'])} m lower (same point); thigh {fnum(h['thigh'])} m; shank {fnum(h['shank'])} m; ankle pitch and roll",
        f"  {fnum(h['ankle_height'])} m above the sole (same point). Foot box {' x '.join(fnum(x) for x in h['foot_box'])} m,",
        "  9 cm behind and 13 cm in front of the ankle. Hip pitch height standing: 0.79 m.",
        f"- Torso: chest yaw {fnum(h['chest_yaw_up'])} m and chest pitch {fnum(h['chest_yaw_up'] + h['chest_pitch_up'])} m above the waist; shoulders",
        f"  {fnum(h['shoulder'][2])} m above the chest pitch axis, {fnum(h['shoulder'][1])} m to the side (standing: z = 1.31 m);",
        f"  neck yaw {fnum(h['neck_yaw_up'])} m and neck pitch {fnum(h['neck_yaw_up'] + h['neck_pitch_up'])} m above the chest pitch axis; head box",
        "  0.17 x 0.15 x 0.14 m.",
        f"- Arm: upper arm {fnum(h['upper_arm'])} m, forearm {fnum(h['forearm'])} m, wrist yaw/pitch/roll at one point, hand box",
        "  0.05 x 0.08 x 0.10 m below the wrist, one finger hinged 6 cm in front of the wrist axis that closes",
        "  against the back (+x face) of the hand.",
        "- Link names: `waist` (pelvis), `*_hip_p_link` = thigh, `*_knee_p_link` = shank, `*_foot`,",
        "  `chest_p_link` = torso, `neck_p_link` = head, `*_shoulder_y_link` = upper arm,",
        "  `*_elbow_p_link` = forearm, `*_hand`, `*_finger`. The other links are actuator housings",
        "  (mass and visuals, no collision geometry). Only links with collision boxes: waist, thighs, shanks,",
        "  feet (2 boxes: sole plate = box 0, ankle block), chest, head, upper arms, forearms, hands, fingers.",
        "",
        "Masses (kg, per side where paired): " + ", ".join(f"{k} {fnum(v)}" for k, v in MASSES.items()) + ".",
        "",
        "Joint positive directions (same axis on both sides; roll ranges are mirrored):",
        "",
    ]
    for table in (LEG_JOINTS, TORSO_JOINTS, ARM_JOINTS, [GRIPPER]):
        for row in table:
            lines.append(f"- `{row[0]}`: {row[6]}.")
    lines += ["", "Joints (in file order):", ""] + joint_table(m)
    lines += ["", "Surfaces (`humanoid.surfaces.yaml`; both sides, prefix `l_` / `r_`):", "",
              "| surface | link | normal (link frame) | what |", "|---|---|---|---|"]
    for s in hum_surfaces:
        if s["name"].startswith("l_"):
            kind = s["name"][2:]
            lines.append(f"| `{s['name']}`, `r_{kind}` | `{s['link']}`, `{s['link'].replace('l_', 'r_', 1)}` "
                         f"| {yvec(s['normal'])} | {SURFACE_DOCS[kind]} |")
    lines += ["", "Checks printed by the script (zero configuration unless stated):", ""]
    lines += ["    " + l for l in report["lines"]]
    lines += [
        "",
        "## environments",
        "Fixed one-tree URDFs with root link `floor`; every piece is a link attached to `floor` by a fixed",
        "joint. Boxes only, with inertials (the masses are nominal: the environment never moves).",
        f"The floor is a {' x '.join(fnum(x) for x in FLOOR['size'])} m slab, x from "
        f"{fnum(FLOOR['center_xy'][0] - FLOOR['size'][0] / 2)} to {fnum(FLOOR['center_xy'][0] + FLOOR['size'][0] / 2)} m, "
        f"y from {fnum(-FLOOR['size'][1] / 2)} to {fnum(FLOOR['size'][1] / 2)} m, top face at z = 0 (surface `floor`).",
        "",
        "### `desk_room/` (scenario 1: walk to the desk and sit down)",
        f"- desk (link `desk`): top board {fnum(DESK['board'][0])} (x) x {fnum(DESK['board'][1])} (y) x {fnum(DESK['board'][2])} m, "
        f"top face at z = {fnum(DESK['top'])} m, centred at x = {fnum(DESK['x'])} m (near edge x = "
        f"{fnum(DESK['x'] - DESK['board'][0] / 2)} m, far edge {fnum(DESK['x'] + DESK['board'][0] / 2)} m), four "
        f"{fnum(DESK['leg'])} m square legs. Knee room under the board: {fnum(DESK['top'] - DESK['board'][2])} m.",
        f"- chair (link `chair`, facing +x): seat {fnum(CHAIR['seat'][0])} x {fnum(CHAIR['seat'][1])} x {fnum(CHAIR['seat'][2])} m, "
        f"top face at z = {fnum(CHAIR['seat_top'])} m, centred at x = {fnum(CHAIR['x'])} m (x "
        f"{fnum(CHAIR['x'] - CHAIR['seat'][0] / 2)} to {fnum(CHAIR['x'] + CHAIR['seat'][0] / 2)} m); backrest "
        f"{fnum(CHAIR['back'][0])} m thick, from the seat up to z = {fnum(CHAIR['seat_top'] + CHAIR['back'][1])} m, its front "
        f"face at x = {fnum(CHAIR['x'] - CHAIR['seat'][0] / 2 + CHAIR['back'][0])} m; four {fnum(CHAIR['leg'])} m square legs, "
        f"set {fnum(CHAIR['leg_inset_x'])} m in from the seat's front and back edges (room for the heels under the seat).",
        f"  The gap between the seat's front edge and the desk is "
        f"{fnum(DESK['x'] - DESK['board'][0] / 2 - CHAIR['x'] - CHAIR['seat'][0] / 2)} m: the humanoid can stand straight in it,",
        "  feet where they will be when seated, then sit back (its hanging hands are at the height of the",
        "  desk's board, so the arms must be lifted a little).",
        "- Surfaces: `floor` (floor +z), `desk_top` (desk box 0, +z), `chair_seat` (chair box 0, +z),",
        "  `chair_back` (chair box 1, +x: the backrest's front face).",
        "- The robot starts at the origin facing +x; the chair's back is toward it, so it walks around the",
        "  chair. The script finds a symmetric seated posture (thighs on the seat, feet flat, forearms",
        "  on the desk) that is collision-free; see the checks above.",
        "",
        "### `flat_ground/` (walking)",
        "- Just the floor; surface `floor`.",
        "",
        "### `wall/` (hand on the wall)",
        f"- Floor plus a wall slab {' x '.join(fnum(x) for x in WALL['size'])} m (x, y, z) whose -x face is at x = "
        f"{fnum(WALL['x'])} m, facing the robot standing at the origin. Surfaces: `floor`, `wall` (wall box 0, -x).",
        "",
    ]
    return "\n".join(lines)


# ------------------------------------------------------------------------------------------------


def verify_surfaces(model, surfaces):
    """Every robot surface lies on a face of its link's collision box and is CCW about its normal;
    every box_face surface names an existing box."""
    for s in surfaces:
        assert s["link"] in model.links, s
        if "point" in s:  # a point surface: a sphere of `radius` centred at `point`
            out.append(f"    point: {yvec(s['point'])}")
            out.append(f"    radius: {fnum(s['radius'])}")
        elif "box_face" in s:
            assert s["box_index"] < len(model.links[s["link"]].collision_boxes()), s
            continue
        assert ccw_area(s["vertices"], s["normal"]) > 0, s["name"]
        on_face = False
        for b in model.links[s["link"]].collision_boxes():
            k = [i for i in range(3) if abs(s["normal"][i]) > 0.5][0]
            plane = b.xyz[k] + s["normal"][k] * b.half()[k]
            if all(abs(v[k] - plane) < 1e-12 and
                   all(b.xyz[i] - b.half()[i] - 1e-12 <= v[i] <= b.xyz[i] + b.half()[i] + 1e-12 for i in range(3))
                   for v in s["vertices"]):
                on_face = True
        assert on_face, s["name"]
    names = [s["name"] for s in surfaces]
    assert len(set(names)) == len(names)


def write(path, text, written):
    full = os.path.join(ASSETS, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)
    written.append(os.path.relpath(full, ROOT))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="print every clearance found")
    args = ap.parse_args()

    hum = build_humanoid()
    hum_surf = humanoid_surfaces(hum)
    verify_surfaces(hum, hum_surf)
    desk_room, desk_surf = build_desk_room()
    flat, flat_surf = build_flat_ground()
    wall, wall_surf = build_wall()
    for env, surf in ((desk_room, desk_surf), (flat, flat_surf), (wall, wall_surf)):
        verify_surfaces(env, surf)

    closest = []   # printed with --check only, never written to the README
    lines, _ = report_humanoid(hum, hum_surf, desk_room, closest)
    lines += report_standing_gap(hum, desk_room)
    poses = fk(hum, {}, (0.0, 0.0, H["waist_height"]))
    boxes = world_boxes(hum, poses, "robot")
    height = max(b[3][2] + b[5][2] for b in boxes)
    report = dict(lines=lines, height=height, joints=sum(1 for j in hum.joints if j.type == "revolute"))

    written = []
    write("robots/humanoid/humanoid.urdf", hum.urdf(), written)
    write("robots/humanoid/humanoid.surfaces.yaml",
          surfaces_yaml("humanoid contact surfaces (link frames)", hum_surf), written)
    write("environments/desk_room/desk_room.urdf", desk_room.urdf(), written)
    write("environments/desk_room/desk_room.surfaces.yaml",
          surfaces_yaml("desk_room contact surfaces", desk_surf), written)
    write("environments/flat_ground/flat_ground.urdf", flat.urdf(), written)
    write("environments/flat_ground/flat_ground.surfaces.yaml",
          surfaces_yaml("flat_ground contact surfaces", flat_surf), written)
    write("environments/wall/wall.urdf", wall.urdf(), written)
    write("environments/wall/wall.surfaces.yaml", surfaces_yaml("wall contact surfaces", wall_surf), written)
    write("README.md", readme(hum, hum_surf, [desk_room, flat, wall], report), written)

    for p in written:
        print("wrote", p)
    for l in lines:
        print(l)
    if args.check:
        print("closest collision-box pairs of non-adjacent links at the zero configuration:")
        for l in closest:
            print(l)
    return 0


if __name__ == "__main__":
    sys.exit(main())
