#!/usr/bin/env python3
"""adm_twins.py [XML...]: writes the Adams dataset twin NAME.adm of each bundled
MotionSolve XML example (default: every harness/examples/*.xml), the same model
statement for statement, as MotionSolve's pre-processor maps ADM onto XML
(docs/interface.md §9). tests/test_adm_twins.c reads each pair and fails when
a twin no longer describes its XML's model: rerun this after editing an
example. Numbers are written as the XML writes them, so that both readers
parse the same text; direction cosines become ZP/XP points.
Needs python3 (Debian's python3), at development time only."""
import glob
import os
import sys
import xml.etree.ElementTree as ET

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def attrs(el):
    return {k.lower(): v for k, v in el.attrib.items()}


def lines_of(name, head, args):
    """NAME/head, then one argument per continuation line."""
    out = ["%s/%s" % (name, head)] if head else ["%s/" % name]
    if args and head and len(", ".join(args)) + len(out[0]) < 70:
        out[0] += ", " + ", ".join(args)
        return out
    out += [", " + a for a in args]
    return out


def routine(a):
    dll = a.get("usrsub_dll_name")
    fnc = a.get("usrsub_fnc_name")
    if dll in (None, "", "NULL"):
        dll = None
    if fnc in (None, "", "NULL"):
        fnc = None
    ders = [a[k] for k in ("usrsub_der1_name", "usrsub_der2_name", "usrsub_der3_name",
                           "usrsub_der4_name") if a.get(k) not in (None, "", "NULL")]
    if dll is None and fnc is None and not ders:
        return []
    names = [(dll + "::" if dll else "") + (fnc or "")]
    names += [(dll + "::" if dll else "") + d for d in ders]
    return ["ROUTINE = " + ", ".join(names)]


def user(a):
    return ["FUNCTION = " + a["usrsub_param_string"]] + routine(a)


def twin(path):
    tree = ET.parse(path)
    model = tree.getroot().find("Model")
    els = list(model)
    markers = {a.get("id"): a for a in (attrs(e) for e in els if e.tag == "Reference_Marker")}
    ground = [attrs(e)["id"] for e in els if e.tag == "Body_Ground" or
              (e.tag == "Body_Rigid" and attrs(e).get("isground", "").upper() == "TRUE")]
    ground_markers = [m["id"] for m in markers.values() if m["body_id"] in ground]
    world_axes = [i for i in ground_markers if not any(
        k in markers[i] for k in ("a00", "a01", "a02", "a10", "a11", "a12", "a20", "a21", "a22",
                                  "psi", "theta", "phi", "rm_id"))]
    name = os.path.basename(path)[:-4]
    out = ["%s: the Adams dataset twin of %s.xml (scripts/adm_twins.py)" % (name, name),
           "! The same model as %s.xml, statement for statement: tests/test_adm_twins.c" % name,
           "! reads both and runs both. Edit the XML, then rerun scripts/adm_twins.py."]
    seen = set()

    def statement(kind, ident, args):
        if ident is not None:
            if (kind, ident) in seen:
                sys.exit("%s: %s/%s twice: no twin can hold it" % (path, kind, ident))
            seen.add((kind, ident))
        out.extend(lines_of(kind, ident, args))

    for e in els:
        a = attrs(e)
        tag = e.tag
        i = a.get("id")
        if tag == "Param_Unit":
            statement("UNITS", None, ["FORCE = " + a["force_unit"], "MASS = " + a["mass_unit"],
                                      "LENGTH = " + a["length_unit"], "TIME = " + a["time_unit"]])
        elif tag == "Force_Gravity":
            statement("ACCGRAV", None, ["IGRAV = " + a.get("grav_x", "0"),
                                        "JGRAV = " + a.get("grav_y", "0"),
                                        "KGRAV = " + a.get("grav_z", "0")])
        elif tag == "Reference_String":
            statement("STRING", i, ["STRING = " + a["string"]])
        elif tag == "Body_Ground":
            statement("PART", i, ["GROUND"])
        elif tag == "Body_Rigid":
            if a.get("isground", "").upper() == "TRUE":
                statement("PART", i, ["GROUND"])
                continue
            ip = [a["inertia_xx"], a["inertia_yy"], a["inertia_zz"]]
            if any(k in a for k in ("inertia_xy", "inertia_xz", "inertia_yz")):
                ip += [a.get("inertia_xy", "0"), a.get("inertia_xz", "0"), a.get("inertia_yz", "0")]
            args = ["MASS = " + a["mass"], "CM = " + a["cg_id"]]
            if "im_id" in a:
                args.append("IM = " + a["im_id"])
            args.append("IP = " + ", ".join(ip))
            for x, k in (("VX", "v_ic_x"), ("VY", "v_ic_y"), ("VZ", "v_ic_z")):
                if k in a:
                    args.append("%s = %s" % (x, a[k]))
            ws = [(x, a[k]) for x, k in (("WX", "w_ic_x"), ("WY", "w_ic_y"), ("WZ", "w_ic_z")) if k in a]
            cm = markers[a["cg_id"]]
            if ws and any(k in cm for k in ("a00", "a01", "a02", "a10", "a11", "a12", "a20", "a21",
                                            "a22", "psi", "theta", "phi")):
                # the XML's are in world axes, Adams' about the CM marker's: about a
                # ground marker with the world's axes instead
                args.append("WM = " + world_axes[0])
            args += ["%s = %s" % w for w in ws]
            statement("PART", i, args)
        elif tag == "Reference_Marker":
            args = ["PART = " + a["body_id"]]
            q = [a.get("pos_x", "0"), a.get("pos_y", "0"), a.get("pos_z", "0")]
            if any(v not in ("0", "0.0") for v in q):
                args.append("QP = " + ", ".join(q))
            if "rm_id" in a:
                args.append("RM = " + a["rm_id"])
            if any(k in a for k in ("psi", "theta", "phi")):
                args.append("REULER = " + ", ".join(a.get(k, "0") for k in ("psi", "theta", "phi")))
            elif any(k in a for k in ("a00", "a01", "a02", "a10", "a11", "a12", "a20", "a21", "a22")):
                col = lambda j: [float(a.get("a%d%d" % (r, j), "1" if r == j else "0")) for r in range(3)]
                qf = [float(v) for v in q]
                zp = [repr(qf[r] + col(2)[r]) for r in range(3)]
                xp = [repr(qf[r] + col(0)[r]) for r in range(3)]
                args += ["ZP = " + ", ".join(zp), "XP = " + ", ".join(xp)]
            elif any(k in a for k in ("e0", "e1", "e2", "e3", "yaw", "pitch", "roll")):
                sys.exit("%s: marker %s: no dataset form for its orientation" % (path, i))
            statement("MARKER", i, args)
        elif tag == "Constraint_Joint":
            statement("JOINT", i, [a["type"].upper(), "I = " + a["i_marker_id"],
                                   "J = " + a["j_marker_id"]])
        elif tag == "Constraint_Coupler":
            joints = [a[k] for k in ("joint1_id", "joint2_id", "joint3_id") if k in a]
            args = ["JOINTS = " + ", ".join(joints)]
            free = [a.get(k) for k in ("freedom_1", "freedom_2", "freedom_3")[:len(joints)]]
            if all(free):
                args.append("TYPE = " + ":".join(f.upper() for f in free))
            if "coefficients" in a:
                args.append("SCALES = " + a["coefficients"])
            else:
                args += user(a)
            statement("COUPLER", i, args)
        elif tag == "Motion_Joint":
            args = ["JOINT = " + a["joint_id"]]
            if "motion_type" in a:
                args.append({"T": "TRANSLATION", "R": "ROTATION"}[a["motion_type"].upper()])
            args.append({"D": "DISPLACEMENT", "V": "VELOCITY",
                         "A": "ACCELERATION"}[a.get("val_type", "D").upper()])
            for x, k in (("ICDISP", "ic_disp"), ("ICVEL", "ic_vel")):
                if k in a:
                    args.append("%s = %s" % (x, a[k]))
            if a.get("type", "").upper() == "USERSUB" or "usrsub_param_string" in a:
                args += user(a)
            else:
                args.append("FUNCTION = " + a["expr"])
            statement("MOTION", i, args)
        elif tag == "Force_Vector_TwoBody":
            kind = {"forceandtorque": "GFORCE", "forceonly": "VFORCE",
                    "torqueonly": "VTORQUE"}[a.get("type", "ForceAndTorque").lower()]
            args = ["I = " + a["i_marker_id"], "JFLOAT = " + a["j_floating_marker_id"]]
            if "ref_marker_id" in a:
                args.append("RM = " + a["ref_marker_id"])
            statement(kind, i, args + user(a))
        elif tag == "Force_Field" and "usrsub_param_string" in a:
            statement("FIELD", i, ["I = " + a["i_marker_id"], "J = " + a["j_marker_id"]] + user(a))
        elif tag == "Force_Field":  # linear: Adams lists KMATRIX and CMATRIX by columns
            args = ["I = " + a["i_marker_id"], "J = " + a["j_marker_id"]]
            for key, m in (("KMATRIX", "k"), ("CMATRIX", "c")):
                names = ["%s%d%d" % (m, r, c) for c in range(1, 7) for r in range(1, 7)]
                if any(n in a for n in names):  # a column a line
                    values = [a.get(n, "0") for n in names]
                    rows = [", ".join(values[k:k + 6]) for k in range(0, 36, 6)]
                    args += ["%s = %s," % (key, rows[0])] + [r + "," for r in rows[1:5]] + [rows[5]]
            if "cratio" in a:
                args.append("CRATIO = " + a["cratio"])
            for key, prefix in (("LENGTH", "length_"), ("FORCE", "preload_")):
                names = [prefix + n for n in ("x", "y", "z", "tx", "ty", "tz")]
                if any(n in a for n in names):
                    args.append("%s = %s" % (key, ", ".join(a.get(n, "0") for n in names)))
            statement("FIELD", i, args)
        elif tag == "Force_Vector_OneBody":
            if "usrsub_param_string" in a:
                sys.exit("%s: Force_Vector_OneBody %s: a user routine on one body has no twin" % (path, i))
            kind = {"forceonly": "VFORCE", "torqueonly": "VTORQUE"}.get(a.get("type", "").lower(), "GFORCE")
            args = ["I = " + a["marker_id"], "JFLOAT = " + ground_markers[0]]
            if "ref_marker_id" in a:
                args.append("RM = " + a["ref_marker_id"])
            for c in ("fx", "fy", "fz", "tx", "ty", "tz"):
                if c + "_expression" in a:
                    args.append("%s = %s" % (c.upper(), a[c + "_expression"]))
            statement(kind, i, args)
        elif tag == "Force_Scalar_TwoBody":
            args = ["TRANSLATION" if a["type"].upper() == "FORCE" else "ROTATION",
                    "I = " + a["i_marker_id"], "J = " + a["j_marker_id"]]
            if a.get("is_action_only", "").upper() == "TRUE":
                args.append("ACTIONONLY")
            if "usrsub_param_string" in a:
                args += user(a)
            else:
                args.append("FUNCTION = " + a.get("val", a.get("val_expression")))
            statement("SFORCE", i, args)
        elif tag == "Force_SpringDamper":
            rotational = a["type"].upper() == "ROTATIONAL"
            keys = ("KT", "CT", "ANGLE", "TORQUE") if rotational else ("K", "C", "LENGTH", "FORCE")
            args = ["ROTATIONAL" if rotational else "TRANSLATIONAL", "I = " + a["i_marker_id"],
                    "J = " + a["j_marker_id"]]
            for key, attr in zip(keys, ("stiffness", "damping", "length", "preload")):
                if attr in a:
                    args.append("%s = %s" % (key, a[attr]))
            statement("SPRINGDAMPER", i, args)
        elif tag == "Force_Bushing":
            args = ["I = " + a["i_marker_id"], "J = " + a["j_marker_id"]]
            for key, names in (("K", ("kx", "ky", "kz")), ("C", ("cx", "cy", "cz")),
                               ("KT", ("ktx", "kty", "ktz")), ("CT", ("ctx", "cty", "ctz")),
                               ("FORCE", ("preload_x", "preload_y", "preload_z")),
                               ("TORQUE", ("preload_tx", "preload_ty", "preload_tz"))):
                if any(n in a for n in names):
                    args.append("%s = %s" % (key, ", ".join(a.get(n, "0") for n in names)))
            statement("BUSHING", i, args)
        elif tag == "Force_Beam":
            if any(k.startswith("preload") for k in a):
                sys.exit("%s: Force_Beam %s: Adams' BEAM has no preload" % (path, i))
            args = ["I = " + a["i_marker_id"], "J = " + a["j_marker_id"]]
            for key, attr in (("LENGTH", "length"), ("EMODULUS", "e"), ("GMODULUS", "g"),
                              ("AREA", "area"), ("IXX", "ixx"), ("IYY", "iyy"), ("IZZ", "izz"),
                              ("ASY", "asy"), ("ASZ", "asz"), ("CRATIO", "cratio")):
                if attr in a:
                    args.append("%s = %s" % (key, a[attr]))
            if "cmatrix" in a:
                args.append("CMATRIX = " + ", ".join(a["cmatrix"].replace(",", " ").split()))
            statement("BEAM", i, args)
        elif tag == "Force_StateEqn":
            args = ["I = " + a["i_marker_id"], "JFLOAT = " + a["j_floating_marker_id"],
                    "RM = " + a["ref_marker_id"], "X = " + a["x_array_id"]]
            for x, k in (("U", "u_array_id"), ("IC", "ic_array_id")):
                if a.get(k, "0") != "0":
                    args.append("%s = %s" % (x, a[k]))
            if a.get("is_static_hold", "").upper() == "TRUE":
                args.append("STATIC_HOLD")
            statement("FORCE_STATEEQN", i, args + user(a))
        elif tag == "Reference_Array":
            t = a["type"].upper()
            data = (e.text or "").split()
            if t in ("X", "Y"):
                args = [t, "SIZE = " + a["num_element"]]
            elif t == "U":
                ids = a["variable_id"].replace(",", " ").split() if "variable_id" in a else data
                args = [t, "VARIABLES = " + ", ".join(ids)]
            else:
                args = [t, "NUMBERS = " + ", ".join(v.strip(",") for v in data)]
            statement("ARRAY", i, args)
        elif tag == "Reference_Variable":
            if a.get("type", "EXPRESSION").upper() == "USERSUB":
                statement("VARIABLE", i, user(a))
            else:
                statement("VARIABLE", i, ["FUNCTION = " + a["expr"]])
        elif tag == "Reference_Spline":
            data = (e.text or "").replace(",", " ").split()
            args = ["X = " + ", ".join(data[0::2]), "Y = " + ", ".join(data[1::2])]
            if a.get("linear_extrap", "").upper() == "TRUE":
                args.append("LINEAR_EXTRAPOLATE")
            statement("SPLINE", i, args)
        else:
            sys.exit("%s: <%s> has no twin in this script" % (path, tag))
    out.append("END")
    return "\n".join(out) + "\n"


def main():
    paths = sys.argv[1:] or sorted(glob.glob(os.path.join(root, "harness/examples/*.xml")))
    for p in paths:
        text = twin(p)
        with open(p[:-4] + ".adm", "w") as f:
            f.write(text)
        print("wrote", os.path.relpath(p[:-4] + ".adm", root))


main()
