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
Needs python3 (Debian's python3), at development time only."""
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
  bushings), so none is redundant.
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


if __name__ == "__main__":
    main()
