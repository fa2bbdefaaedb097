#!/usr/bin/env python3
"""vehicle_joints.py: writes harness/examples/full_vehicle_joints.xml, the full vehicle of
harness/examples/full_vehicle.xml with real joints where its ball joints and wheel bearings
are stand-in bushings, everything else copied line for line:

- the 12 ball joints that are Force_Vector_TwoBody bushings on full_vehicle_ball_joint.gbs
  (string 35: the control arms' lower and upper ball joints and the tie rods' or toe links'
  outer joints) become SPHERICAL joints between the same I and J markers (the joint keeps
  the element's id: JOINT/20 is the former front left lower ball joint);
- the 4 wheel bearings (string 33, Force_Vector_TwoBody) become REVOLUTE joints between the
  same markers, turned so that their z axis is the wheel's spin axis (world y): the bearing
  markers had the world's axes (the bushing's free direction was its y), a revolute joint
  turns about z. Nothing else uses those markers.

The bushings of string 35 that are Force_Field elements (tie rods' inner joints, drop
links) stay bushings. The new model's header comment says what changed and why (HEADER
below). Rerun this after editing full_vehicle.xml, then scripts/adm_twins.py
harness/examples/full_vehicle_joints.xml for its dataset twin.

Two measurements on run --out CSVs (docs/examples.md, docs/performance.md "The full
vehicle on joints"):
  vehicle_joints.py compare BUSHINGS.csv JOINTS.csv
      the table of docs/examples.md: the body's heave, roll and pitch, the engine's
      pitch, the wheels' rise, from their start, extremes and largest difference;
  vehicle_joints.py errors REFERENCE.csv RUN.csv...
      the error of each run on the slow outputs (the body's and the engine's states,
      bodies 2 and 5): per kind (positions, quaternions, velocities, angular
      velocities) the largest difference over the output times over the kind's largest
      excursion from the start (positions, quaternions) or largest value (velocities);
      the largest over kinds and bodies, and where.
Needs python3 (Debian's python3), at development time only."""
import csv
import math
import os
import re
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
source = os.path.join(root, "harness", "examples", "full_vehicle.xml")
target = os.path.join(root, "harness", "examples", "full_vehicle_joints.xml")

HEADER = """<!--
  The full vehicle of full_vehicle.xml on real joints (written by
  scripts/vehicle_joints.py from full_vehicle.xml: edit that and rerun the script).

  What changed: the 12 ball joints (the lower and upper control arms' and the tie
  rods' or toe links' outer joints, Force_Vector_TwoBody bushings on
  full_vehicle_ball_joint.gbs) are SPHERICAL joints, and the 4 wheel bearings
  (full_vehicle_wheel_bearing.gbs) REVOLUTE joints, each Constraint_Joint with
  the id of the element it replaces (JOINT/17 the front left bearing, JOINT/20 its
  lower ball joint, ...). The bearings' markers are turned so that their z axis,
  the revolute's, is the wheel's spin axis (world y); they had the world's axes.
  Everything else is full_vehicle.xml's, line for line: 34 free bodies, 57
  bushing elements (8 GFOSUB, 49 FIESUB; the tie rods' inner joints and the drop
  links stay ball-joint bushings), the preloads, the bump and the engine torque.

  Why: the bushings stood in for joints (30 000 N/mm in translation, 2000 N mm/rad
  in rotation for a ball joint; 50 000 N/mm and 5e7 N mm/rad for a bearing, free
  about the spin axis). The joints hold exactly what those held stiffly and drop
  their small rotational stiffness and damping (a ball joint's 2000 N mm/rad, a
  bearing's drag of 10 N mm s/rad: the tires, braked, hold the wheels' spin). The
  joints join moving bodies (knuckle to wheel, arms, tie rod), 56 equations; none
  closes a loop of joints alone (the arms and tie rods reach the subframes through
  bushings), so none is redundant: the harness removes no equation and the
  assembly moves nothing.

  On the load case (docs/examples.md) the body heaves 2.55 mm and rolls
  4.5e-3 rad (2.44 mm and 4.6e-3 rad on the bushings), the left wheels rise 17.3
  and 12.2 mm; the joints hold to 3e-11 mm (DOPRI5) and 3e-10 mm (BDF).
-->
"""

BALL_JOINT, BEARING = "35", "33"
AXLE = ' a00="1" a10="0" a20="0" a01="0" a11="0" a21="-1" a02="0" a12="1" a22="0"'

ELEMENT = re.compile(
    r'( *)<Force_Vector_TwoBody id="(\d+)" label="([^"]*)" type="ForceAndTorque" '
    r'i_marker_id="(\d+)" j_floating_marker_id="(\d+)" ref_marker_id="(\d+)"\s*'
    r'usrsub_param_string="USER\((\d+), (\d+), (\d+)\)" usrsub_fnc_name="ABM_BUSHING" '
    r'usrsub_dll_name="libusrsub.so"/>\n')


def main():
    with open(source) as f:
        text = f.read()
    found = {BALL_JOINT: 0, BEARING: 0}
    axle_markers = []

    def joint(m):
        indent, ident, label, i, j, ref, ui, uj, string = m.groups()
        if string not in found:
            return m.group(0)
        if (ui, uj) != (i, j) or ref != j:
            sys.exit("%s: element %s (%s): its USER markers are not its I and J" %
                     (source, ident, label))
        found[string] += 1
        kind = "SPHERICAL" if string == BALL_JOINT else "REVOLUTE"
        if string == BEARING:
            axle_markers.extend([i, j])
        return '%s<Constraint_Joint id="%s" label="%s" type="%s" i_marker_id="%s" j_marker_id="%s"/>\n' % (
            indent, ident, label, kind, i, j)

    text = ELEMENT.sub(joint, text)
    if found != {BALL_JOINT: 12, BEARING: 4}:
        sys.exit("%s: expected 12 ball joints and 4 bearings as Force_Vector_TwoBody, found %d and %d"
                 % (source, found[BALL_JOINT], found[BEARING]))
    for marker in axle_markers:
        if len(re.findall(r'marker_id="%s"' % marker, text)) != 1:
            sys.exit("%s: marker %s is used elsewhere than its bearing: turning it would move that"
                     % (source, marker))
        pattern = re.compile(r'(<Reference_Marker id="%s" [^>]*?)( label="[^"]*"/>)' % marker)
        lines = pattern.findall(text)
        if len(lines) != 1 or re.search(r' (a\d\d|psi|theta|phi|e\d|rm_id)=', lines[0][0]):
            sys.exit("%s: bearing marker %s: not one marker line with the world's axes"
                     % (source, marker))
        text = pattern.sub(lambda m: m.group(1) + AXLE + m.group(2), text)
    head = re.compile(r"<!--.*?-->\n", re.S)
    if not head.search(text):
        sys.exit("%s: no header comment" % source)
    text = head.sub(lambda m: HEADER, text, count=1)
    with open(target, "w") as f:
        f.write(text)
    print("wrote %s" % os.path.relpath(target, root))


def load(path):
    with open(path) as f:
        rows = csv.reader(f)
        head = next(rows)
        return {n: i for i, n in enumerate(head)}, [[float(v) for v in r] for r in rows]


def angles(c, row, body):
    q0, q1, q2, q3 = (row[c["body%d.q%d" % (body, k)]] for k in range(4))
    roll = math.atan2(2 * (q0 * q1 + q2 * q3), 1 - 2 * (q1 * q1 + q2 * q2))
    return roll, math.asin(max(-1.0, min(1.0, 2 * (q0 * q2 - q3 * q1))))


def outputs(c, rows):
    def rel(f):
        return [f(r) - f(rows[0]) for r in rows]
    out = [("body heave (mm)", rel(lambda r: r[c["body2.z"]])),
           ("body roll (rad)", rel(lambda r: angles(c, r, 2)[0])),
           ("body pitch (rad)", rel(lambda r: angles(c, r, 2)[1])),
           ("engine pitch (rad)", rel(lambda r: angles(c, r, 5)[1]))]
    for body, name in ((8, "front left"), (14, "front right"), (20, "rear left"), (26, "rear right")):
        out.append(("%s wheel rise (mm)" % name, rel(lambda r, b=body: r[c["body%d.z" % b]])))
    return out


def compare(bushings, joints):
    ca, ra = load(bushings)
    cb, rb = load(joints)
    if [r[0] for r in ra] != [r[0] for r in rb]:
        sys.exit("%s and %s: not the same output times" % (bushings, joints))
    print("| output | bushings: extreme | joints: extreme | largest difference (at t) |")
    print("|---|---|---|---|")
    for (name, a), (_, b) in zip(outputs(ca, ra), outputs(cb, rb)):
        d = [abs(x - y) for x, y in zip(a, b)]
        i = d.index(max(d))
        print("| %s | %.4g | %.4g | %.2g (%.3f s) |" % (name, max(a, key=abs), max(b, key=abs),
                                                         d[i], ra[i][0]))


def errors(reference, runs):
    cr, ref = load(reference)
    kinds = (("positions", "xyz"), ("quaternions", ("q0", "q1", "q2", "q3")),
             ("velocities", ("vx", "vy", "vz")), ("angular velocities", ("wx", "wy", "wz")))
    for path in runs:
        c, rows = load(path)
        if [r[0] for r in rows] != [r[0] for r in ref]:
            sys.exit("%s: not the output times of %s" % (path, reference))
        worst, where = 0.0, ""
        for body in (2, 5):
            for kind, comps in kinds:
                cols = ["body%d.%s" % (body, s) for s in comps]
                moving = kind in ("positions", "quaternions")
                scale = max(abs(r[cr[n]] - (ref[0][cr[n]] if moving else 0.0))
                            for r in ref for n in cols)
                e = max(abs(r[c[n]] - q[cr[n]]) for r, q in zip(rows, ref) for n in cols) / scale
                if e > worst:
                    worst, where = e, "body %d's %s" % (body, kind)
        print("%s: %.3g (%s)" % (path, worst, where))


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "compare":
        compare(sys.argv[2], sys.argv[3])
    elif len(sys.argv) >= 4 and sys.argv[1] == "errors":
        errors(sys.argv[2], sys.argv[3:])
    elif len(sys.argv) == 1:
        main()
    else:
        sys.exit("usage: vehicle_joints.py | compare BUSHINGS.csv JOINTS.csv |"
                 " errors REFERENCE.csv RUN.csv...")
