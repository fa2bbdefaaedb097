/*
 * The dataset's statements (docs/interface.md §9): for each, what the
 * harness does with it, its keywords (kind of value, count, required, the
 * statement an id names) and its builder. Statements that only produce
 * output are accepted unread; analysis settings the model has no place for
 * are noted; those that act on the dynamics and are not modelled are read
 * over with a warning (run refuses); a few are refused with the reason.
 * FORCE_STATEEQN is this harness's statement for MotionSolve's
 * Force_StateEqn, which Adams has no statement for (docs/sources.md).
 */
#include "model/adm/reader.h"

#define K(name, kind, lo, hi, req, ref) {name, kind, lo, hi, req, 0, ref, 0}
#define FLAG(name) K(name, HX_ADM_FLAG, 0, 0, 0, NULL)
#define ID(name, ref) K(name, HX_ADM_ID, 1, 1, 0, ref)
#define NEED_ID(name, ref) K(name, HX_ADM_ID, 1, 1, 1, ref)
#define REAL(name, n) K(name, HX_ADM_REAL, n, n, 0, NULL)
#define ANGLES(name, n) K(name, HX_ADM_ANGLE, n, n, 0, NULL)
#define WORD(name) K(name, HX_ADM_WORD, 1, 1, 0, NULL)
#define TEXT(name) K(name, HX_ADM_TEXT, 1, 1, 0, NULL)
#define EXPR(name) K(name, HX_ADM_EXPR, 1, 1, 0, NULL)
#define ROUTINES(n) K("ROUTINE", HX_ADM_ROUTINE, 1, n, 0, NULL)
#define LIST_MAX 1000000
#define KEND {NULL, HX_ADM_FLAG, 0, 0, 0, 0, NULL, 0}

static const hx_adm_keyword part[] = {
    FLAG("GROUND"), REAL("MASS", 1), ID("CM", "MARKER"), ID("IM", "MARKER"),
    {"IP", HX_ADM_REAL, 3, 6, 0, 0, NULL, 1}, REAL("QG", 3), ANGLES("REULER", 3), REAL("XG", 3),
    REAL("ZG", 3), REAL("VX", 1), REAL("VY", 1), REAL("VZ", 1), REAL("WX", 1), REAL("WY", 1),
    REAL("WZ", 1), ID("VM", "MARKER"), ID("WM", "MARKER"), WORD("EXACT"), KEND};

static const hx_adm_keyword marker[] = {
    NEED_ID("PART", "PART"), REAL("QP", 3), ANGLES("REULER", 3), REAL("ZP", 3), REAL("XP", 3),
    FLAG("USEXP"), FLAG("FLOATING"), ID("RM", "MARKER"), KEND};

static const hx_adm_keyword joint[] = {
    NEED_ID("I", "MARKER"), NEED_ID("J", "MARKER"), FLAG("REVOLUTE"), FLAG("TRANSLATIONAL"),
    FLAG("CYLINDRICAL"), FLAG("SPHERICAL"), FLAG("UNIVERSAL"), FLAG("HOOKE"), FLAG("CONVEL"),
    FLAG("FIXED"), FLAG("PLANAR"), FLAG("RACKPIN"), FLAG("SCREW"), FLAG("PARALLEL_AXES"),
    FLAG("PERPENDICULAR"), FLAG("INLINE"), FLAG("INPLANE"), FLAG("ORIENTATION"),
    K("IC", HX_ADM_REAL, 1, 2, 0, NULL), REAL("ICTRAN", 2), REAL("ICROT", 2), REAL("PD", 1),
    REAL("PITCH", 1), KEND};

static const hx_adm_keyword jprim[] = {
    NEED_ID("I", "MARKER"), NEED_ID("J", "MARKER"), FLAG("ATPOINT"), FLAG("INLINE"),
    FLAG("INPLANE"), FLAG("ORIENTATION"), FLAG("PARALLEL_AXES"), FLAG("PERPENDICULAR"), KEND};

static const hx_adm_keyword coupler[] = {
    K("JOINTS", HX_ADM_ID, 2, 3, 1, "JOINT"), WORD("TYPE"),
    K("SCALES", HX_ADM_REAL, 2, 3, 0, NULL), EXPR("FUNCTION"), ROUTINES(3), KEND};

static const hx_adm_keyword motion[] = {
    ID("JOINT", "JOINT"), ID("I", "MARKER"), ID("J", "MARKER"), FLAG("TRANSLATION"),
    FLAG("ROTATION"), FLAG("DISPLACEMENT"), FLAG("VELOCITY"), FLAG("ACCELERATION"), FLAG("B1"),
    FLAG("B2"), FLAG("B3"), FLAG("X"), FLAG("Y"), FLAG("Z"),
    K("FUNCTION", HX_ADM_EXPR, 1, 1, 1, NULL), ROUTINES(1), REAL("ICDISP", 1), REAL("ICVEL", 1),
    KEND};

static const hx_adm_keyword gcon[] = {
    ID("I", "MARKER"), K("FUNCTION", HX_ADM_EXPR, 1, 1, 1, NULL), ROUTINES(1), KEND};

static const hx_adm_keyword gforce[] = {
    NEED_ID("I", "MARKER"), NEED_ID("JFLOAT", "MARKER"), ID("RM", "MARKER"), EXPR("FX"),
    EXPR("FY"), EXPR("FZ"), EXPR("TX"), EXPR("TY"), EXPR("TZ"), EXPR("FUNCTION"), ROUTINES(1),
    KEND};

static const hx_adm_keyword vforce[] = {
    NEED_ID("I", "MARKER"), NEED_ID("JFLOAT", "MARKER"), ID("RM", "MARKER"), EXPR("FX"),
    EXPR("FY"), EXPR("FZ"), EXPR("FUNCTION"), ROUTINES(1), KEND};

static const hx_adm_keyword vtorque[] = {
    NEED_ID("I", "MARKER"), NEED_ID("JFLOAT", "MARKER"), ID("RM", "MARKER"), EXPR("TX"),
    EXPR("TY"), EXPR("TZ"), EXPR("FUNCTION"), ROUTINES(1), KEND};

static const hx_adm_keyword sforce[] = {
    NEED_ID("I", "MARKER"), NEED_ID("J", "MARKER"), FLAG("TRANSLATION"), FLAG("ROTATION"),
    FLAG("ACTIONONLY"), K("FUNCTION", HX_ADM_EXPR, 1, 1, 1, NULL), ROUTINES(1), KEND};

static const hx_adm_keyword springdamper[] = {
    NEED_ID("I", "MARKER"), NEED_ID("J", "MARKER"), FLAG("TRANSLATIONAL"), FLAG("ROTATIONAL"),
    REAL("K", 1), REAL("C", 1), REAL("LENGTH", 1), REAL("FORCE", 1), REAL("KT", 1),
    REAL("CT", 1), ANGLES("ANGLE", 1), REAL("TORQUE", 1), KEND};

static const hx_adm_keyword bushing[] = {
    NEED_ID("I", "MARKER"), NEED_ID("J", "MARKER"), REAL("K", 3), REAL("C", 3), REAL("KT", 3),
    REAL("CT", 3), REAL("FORCE", 3), REAL("TORQUE", 3), KEND};

static const hx_adm_keyword beam[] = {
    NEED_ID("I", "MARKER"), NEED_ID("J", "MARKER"), K("LENGTH", HX_ADM_REAL, 1, 1, 1, NULL),
    K("EMODULUS", HX_ADM_REAL, 1, 1, 1, NULL), K("GMODULUS", HX_ADM_REAL, 1, 1, 1, NULL),
    K("AREA", HX_ADM_REAL, 1, 1, 1, NULL), K("IXX", HX_ADM_REAL, 1, 1, 1, NULL),
    K("IYY", HX_ADM_REAL, 1, 1, 1, NULL), K("IZZ", HX_ADM_REAL, 1, 1, 1, NULL), REAL("ASY", 1),
    REAL("ASZ", 1), REAL("CRATIO", 1), REAL("CMATRIX", 21), WORD("FORMULATION"), KEND};

static const hx_adm_keyword field[] = {
    NEED_ID("I", "MARKER"), NEED_ID("J", "MARKER"), EXPR("FUNCTION"), ROUTINES(1),
    REAL("CMATRIX", 36), REAL("KMATRIX", 36), REAL("CRATIO", 1), REAL("FORCE", 6),
    K("LENGTH", HX_ADM_POSE, 6, 6, 0, NULL), KEND};

static const hx_adm_keyword force_stateeqn[] = {
    NEED_ID("I", "MARKER"), NEED_ID("JFLOAT", "MARKER"), NEED_ID("RM", "MARKER"),
    NEED_ID("X", "ARRAY"), ID("U", "ARRAY"), ID("IC", "ARRAY"),
    K("FUNCTION", HX_ADM_EXPR, 1, 1, 1, NULL), ROUTINES(5), FLAG("STATIC_HOLD"), KEND};

static const hx_adm_keyword diff[] = {
    K("FUNCTION", HX_ADM_EXPR, 1, 1, 1, NULL), K("IC", HX_ADM_REAL, 1, 2, 0, NULL),
    FLAG("IMPLICIT"), FLAG("STATIC_HOLD"), ROUTINES(1), KEND};

static const hx_adm_keyword variable[] = {
    K("FUNCTION", HX_ADM_EXPR, 1, 1, 1, NULL), REAL("IC", 1), ROUTINES(1), KEND};

static const hx_adm_keyword array[] = {
    FLAG("X"), FLAG("U"), FLAG("Y"), FLAG("IC"), K("SIZE", HX_ADM_INT, 1, 1, 0, NULL),
    K("NUMBERS", HX_ADM_REAL, 1, LIST_MAX, 0, NULL),
    K("VARIABLES", HX_ADM_ID, 1, LIST_MAX, 0, "VARIABLE"), KEND};

static const hx_adm_keyword string[] = {K("STRING", HX_ADM_TEXT, 1, 1, 1, NULL), KEND};

static const hx_adm_keyword spline[] = {
    K("X", HX_ADM_REAL, 1, LIST_MAX, 1, NULL), K("Y", HX_ADM_REAL, 1, LIST_MAX, 1, NULL),
    FLAG("LINEAR_EXTRAPOLATE"), TEXT("FILE"), TEXT("BLOCK"), ROUTINES(1), KEND};

static const hx_adm_keyword request[] = {
    FLAG("DISPLACEMENT"), FLAG("VELOCITY"), FLAG("ACCELERATION"), FLAG("FORCE"),
    K("I", HX_ADM_INT, 1, 1, 0, NULL), K("J", HX_ADM_INT, 1, 1, 0, NULL),
    K("RM", HX_ADM_INT, 1, 1, 0, NULL), EXPR("F1"), EXPR("F2"), EXPR("F3"), EXPR("F4"),
    EXPR("F5"), EXPR("F6"), EXPR("F7"), EXPR("F8"), EXPR("FUNCTION"), ROUTINES(1),
    {"COMMENT", HX_ADM_TEXT, 1, 1, 0, 1, NULL, 0}, TEXT("TITLE"), TEXT("CNAMES"),
    TEXT("CUNITS"), TEXT("CLABELS"), TEXT("RESULTS_NAME"), KEND};

static const hx_adm_keyword units[] = {
    WORD("FORCE"), WORD("MASS"), WORD("LENGTH"), WORD("TIME"), WORD("SYSTEM"), REAL("UCF", 1),
    KEND};

static const hx_adm_keyword accgrav[] = {REAL("IGRAV", 1), REAL("JGRAV", 1), REAL("KGRAV", 1),
                                         KEND};

static const hx_adm_keyword integrator[] = {
    FLAG("GSTIFF"), FLAG("WSTIFF"), FLAG("HHT"), FLAG("NEWMARK"), FLAG("HASTIFF"),
    FLAG("CONSTANT_BDF"), FLAG("RKF45"), FLAG("ABAM"), FLAG("I3"), FLAG("SI1"), FLAG("SI2"),
    REAL("ERROR", 1), REAL("HMAX", 1), REAL("HMIN", 1), REAL("HINIT", 1),
    K("KMAX", HX_ADM_INT, 1, 1, 0, NULL), K("MAXIT", HX_ADM_INT, 1, 1, 0, NULL),
    WORD("CORRECTOR"), WORD("INTERPOLATE"), WORD("PATTERN"), REAL("ALPHA", 1), REAL("BETA", 1),
    REAL("GAMMA", 1), REAL("ADAPTIVITY", 1), WORD("FORMULATION"), KEND};

static const hx_adm_keyword plant_port[] = {
    K("VARIABLES", HX_ADM_ID, 1, LIST_MAX, 1, "VARIABLE"), KEND};

static const hx_adm_keyword end[] = {KEND};

#define BUILD(name, keywords, build) {name, HX_ADM_BUILD, HX_ADM_ID_REQUIRED, keywords, NULL, build}
#define SETTING(name, why) {name, HX_ADM_SETTING, HX_ADM_ID_ANY, NULL, why, NULL}
#define OUTPUT(name) {name, HX_ADM_OUTPUT, HX_ADM_ID_ANY, NULL, NULL, NULL}
#define UNSIMULATED(name, why) {name, HX_ADM_UNSIMULATED, HX_ADM_ID_REQUIRED, NULL, why, NULL}
#define REFUSED(name, why) {name, HX_ADM_REFUSED, HX_ADM_ID_ANY, NULL, why, NULL}

const hx_adm_spec hx_adm_statements[] = {
    BUILD("PART", part, hx_adm_build_part),
    BUILD("MARKER", marker, hx_adm_build_marker),
    BUILD("JOINT", joint, hx_adm_build_joint),
    BUILD("JPRIM", jprim, hx_adm_build_jprim),
    BUILD("COUPLER", coupler, hx_adm_build_coupler),
    BUILD("MOTION", motion, hx_adm_build_motion),
    BUILD("GCON", gcon, hx_adm_build_gcon),
    BUILD("GFORCE", gforce, hx_adm_build_gforce),
    BUILD("VFORCE", vforce, hx_adm_build_gforce),
    BUILD("VTORQUE", vtorque, hx_adm_build_gforce),
    BUILD("SFORCE", sforce, hx_adm_build_sforce),
    BUILD("FIELD", field, hx_adm_build_field),
    BUILD("SPRINGDAMPER", springdamper, hx_adm_build_springdamper),
    BUILD("BUSHING", bushing, hx_adm_build_bushing),
    BUILD("BEAM", beam, hx_adm_build_beam),
    BUILD("FORCE_STATEEQN", force_stateeqn, hx_adm_build_force_stateeqn),
    BUILD("DIFF", diff, hx_adm_build_diff),
    BUILD("VARIABLE", variable, hx_adm_build_variable),
    BUILD("ARRAY", array, hx_adm_build_array),
    BUILD("STRING", string, hx_adm_build_string),
    BUILD("SPLINE", spline, hx_adm_build_spline),
    BUILD("REQUEST", request, hx_adm_build_request),
    BUILD("PINPUT", plant_port, hx_adm_build_plant_port),
    BUILD("POUTPUT", plant_port, hx_adm_build_plant_port),
    {"UNITS", HX_ADM_BUILD, HX_ADM_ID_NONE, units, NULL, hx_adm_build_units},
    {"ACCGRAV", HX_ADM_BUILD, HX_ADM_ID_NONE, accgrav, NULL, hx_adm_build_accgrav},
    {"INTEGRATOR", HX_ADM_BUILD, HX_ADM_ID_NONE, integrator, NULL, hx_adm_build_integrator},
    {"END", HX_ADM_END, HX_ADM_ID_NONE, end, NULL, NULL},
    OUTPUT("GRAPHICS"), OUTPUT("OUTPUT"), OUTPUT("RESULTS"), OUTPUT("MREQUEST"),
    OUTPUT("FEMDATA"), OUTPUT("LIST"), OUTPUT("NOLIST"), OUTPUT("TITLE"), OUTPUT("PSTATE"),
    SETTING("EQUILIBRIUM", "static equilibrium settings: the harness runs dynamics only"),
    SETTING("KINEMATICS", "kinematic analysis settings: the harness runs dynamics only"),
    SETTING("PREFERENCES", "solver preferences, which the harness's own solvers do not take"),
    SETTING("LSOLVER", "the linear solver of the Adams integrators; the harness's is chosen on"
                       " its command line"),
    SETTING("DEBUG", "solver diagnostics"),
    SETTING("IC", "initial-conditions analysis settings: the harness starts from the model's"
                  " positions and velocities as given"),
    SETTING("ENVIRONMENT", "solver environment settings"),
    SETTING("MATRIX", "a MATRIX is data of elements the harness does not simulate (LSE, FIELD"
                      " matrices given by id, ...)"),
    UNSIMULATED("UCON", "a user constraint, which the harness does not simulate yet"),
    UNSIMULATED("GEAR", "a GEAR (a constraint through a common velocity marker), which the"
                        " harness does not simulate yet"),
    UNSIMULATED("NFORCE", "a multi-point force (NFORCE), which the harness does not simulate"),
    UNSIMULATED("MFORCE", "a modal force on a flexible body, which the harness does not"
                          " simulate"),
    UNSIMULATED("FRICTION", "joint friction, which the harness does not simulate yet"),
    UNSIMULATED("CURVE", "a CURVE (for point-curve and curve-curve constraints), which the"
                         " harness does not simulate yet"),
    UNSIMULATED("SURFACE", "a SURFACE, which the harness does not simulate yet"),
    UNSIMULATED("PTCV", "a point-curve constraint, which the harness does not simulate yet"),
    UNSIMULATED("CVCV", "a curve-curve constraint, which the harness does not simulate yet"),
    UNSIMULATED("POINT_MASS", "a point mass, which the harness does not simulate yet"),
    UNSIMULATED("GSE", "a general state equation (GSE), which the harness does not simulate"
                       " yet (a bushing with states is a FORCE_STATEEQN)"),
    UNSIMULATED("LSE", "a linear state equation, which the harness does not simulate yet"),
    UNSIMULATED("TFSISO", "a transfer function, which the harness does not simulate yet"),
    UNSIMULATED("SENSOR", "a SENSOR (it can stop or change the run), which the harness does not"
                          " evaluate"),
    REFUSED("CONTACT", "contact needs the parts' geometry (Parasolid), which the harness does not"
                       " read"),
    REFUSED("FLEX_BODY", "a flexible body needs its modal neutral file, which the harness does"
                         " not read"),
    REFUSED("CLEARANCE", "a clearance needs the parts' geometry, which the harness does not"
                         " read"),
    REFUSED("EXTERNAL_SYSTEM", "an external system is co-simulation, which the harness does not"
                               " do"),
};
const int hx_adm_statement_count = (int)(sizeof hx_adm_statements / sizeof hx_adm_statements[0]);
