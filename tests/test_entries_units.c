/*
 * The library's values in the model's units, with a host of this test's own
 * that answers c_gtunts as an Adams-compatible solver does (docs/interface.md
 * §1): exactly four sizes, time, length, force, mass, and twelve characters,
 * nothing more. Property files in mm, N, s (one with angles in degrees);
 * models in m, kN, tonne, s; in mm, N, kg, ms; in cm, kgf, g, s; and one
 * without units (only the one in cm, kgf, g, s tells a swap of time and
 * length, or of force and mass, from the right order; the bad sizes below
 * tell each slot). Every expected value is worked by hand in the comments:
 * the bushing, the mount limits, the flexible joint, the state equation's
 * rates and outputs, and a coupler's table (not converted: it has no units).
 */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"
#include "usrsub/solver_abi.h"

#define KGF 9.80665
#define DEG (M_PI / 180.0)

/* ---- the host ------------------------------------------------------------- */

typedef struct unit_system {
    const char *name;
    int exists;
    double time, length, force, mass; /* sizes in SI */
    const char *names;                /* twelve characters */
} unit_system;

static const unit_system m_kn_t_s = {"m, kN, tonne, s", 1, 1.0, 1.0, 1e3, 1e3, "S  M  KN T  "};
static const unit_system mm_n_kg_ms = {"mm, N, kg, ms", 1, 1e-3, 1e-3, 1.0, 1.0, "MS MM N  KG "};
static const unit_system cm_kgf_g_s = {"cm, kgf, g, s", 1, 1.0, 1e-2, KGF, 1e-3, "S  CM KGFG  "};
static const unit_system no_units = {"no units", 0, 0, 0, 0, 0, "            "};

static const unit_system *units;
static const char *strings[8];
static int errors;
static char last_error[1024];

void c_gtunts(int *exists, double *scales, char *names)
{
    *exists = units->exists;
    if (!units->exists)
        return;
    scales[0] = units->time;
    scales[1] = units->length;
    scales[2] = units->force;
    scales[3] = units->mass;
    memcpy(names, units->names, 12);
}

void c_gtstrg(int id, char *string, int *nchars, int *istat)
{
    if (id < 1 || id > 8 || strings[id - 1] == NULL) {
        *istat = -1;
        return;
    }
    const int len = (int)strlen(strings[id - 1]);
    const int n = len < *nchars ? len : *nchars;
    memcpy(string, strings[id - 1], (size_t)n);
    if (n < *nchars)
        string[n] = '\0';
    *nchars = n;
    *istat = 0;
}

void c_errmes(int errflg, const char *msg, int id, const char *endflg)
{
    (void)id, (void)endflg;
    if (errflg) {
        errors++;
        snprintf(last_error, sizeof last_error, "%s", msg);
    }
}

void c_usrmes(int msgflg, const char *msg, int id, const char *msgtyp)
{
    (void)msgflg, (void)msg, (void)id, (void)msgtyp;
}

/* The FIESUB, YFOSUB and coupler entries ask the host nothing. */
void c_sysary(const char *fnc, const int *ipar, int nsize, double *states, int *nstates,
              int *errflg)
{
    (void)fnc, (void)ipar, (void)nsize, (void)states;
    *nstates = 0;
    *errflg = 1;
}

void c_sysfnc(const char *fnc, const int *ipar, int nsize, double *value, int *errflg)
{
    (void)fnc, (void)ipar, (void)nsize;
    *value = 0.0;
    *errflg = 1;
}

/* ---- the files, in mm, N, kg, s -------------------------------------------- */

#define HEADER(TYPE, ANGLE)                                                                   \
    "[HEADER]\nFILE_TYPE = '" TYPE "'\nFILE_VERSION = '1'\nFILE_FORMAT = 'ASCII'\n"           \
    "[UNITS]\nLENGTH = 'mm'\nANGLE = '" ANGLE "'\nFORCE = 'newton'\nMASS = 'kg'\n"          \
    "TIME = 'second'\n"

/* Fx: K = 100 N/mm; Fy: C = 2 N s/mm; Tx: K = 10 N mm/deg. */
static const char gbs[] = HEADER("gbs", "degree")
    "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
    "{ formulation FX FY FZ TX TY TZ }\n"
    "'CONSTANT_STIFFNESS' 1 0 0 1 0 0\n'CONSTANT_DAMPING' 0 1 0 0 0 0\n"
    "[CONSTANT_STIFFNESS_FX]\nK = 100\n[CONSTANT_STIFFNESS_TX]\nK = 10\n"
    "[CONSTANT_DAMPING_FY]\nC = 2\n";

/* x positive side: K = 1000 N/mm^2, E = 2, C = 5 N s/mm, D = 0.5 mm, L = 1 mm;
 * az positive side: K = 100 N mm/deg, E = 1, no damping, L = 1 deg. */
static const char gbi[] = HEADER("gbi", "degree")
    "[MOUNT_LIMITS]\n"
    "IMPACT_PARAMETERS_TRA_X_POS = 1000, 2, 5, 0.5, 1\n"
    "IMPACT_PARAMETERS_TRA_X_NEG = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_TRA_Y_POS = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_TRA_Y_NEG = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_TRA_Z_POS = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_TRA_Z_NEG = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_ROT_X_POS = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_ROT_X_NEG = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_ROT_Y_POS = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_ROT_Y_NEG = 0, 1, 0, 0, 0\n"
    "IMPACT_PARAMETERS_ROT_Z_POS = 100, 1, 0, 0, 1\n"
    "IMPACT_PARAMETERS_ROT_Z_NEG = 0, 1, 0, 0, 0\n";

/* K = diag(100 N/mm x3, 1000 N mm/rad x3) with K[x][ax] = 10 N/rad and
 * K[ax][x] = 10 N mm/mm; preload fx = 5 N, tz = 7 N mm. */
static const char gfj[] = HEADER("gfj", "radian")
    "[STIFFNESS]\n(MATRIX)\n{ x y z ax ay az }\n"
    "100 0 0 10 0 0\n0 100 0 0 0 0\n0 0 100 0 0 0\n"
    "10 0 0 1000 0 0\n0 0 0 0 1000 0\n0 0 0 0 0 1000\n"
    "[PRELOAD]\n{ fx fy fz tx ty tz }\n5 0 0 0 0 7\n";

/* Fx: K = 100 N/mm and a rubber filter R = 20 1/s, K0 = 50 N/mm, C0 = 0.5 N s/mm. */
static const char rubber_gbs[] = HEADER("gbs", "radian")
    "[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
    "{ formulation FX FY FZ TX TY TZ }\n"
    "'CONSTANT_STIFFNESS' 1 0 0 0 0 0\n'RUBBER_DAMPING' 1 0 0 0 0 0\n"
    "[CONSTANT_STIFFNESS_FX]\nK = 100\n"
    "[RUBBER_DAMPING_FX]\nNPRELOADS = 1\n(PRELOAD_1)\nPRELOAD = 0\nR = 20\nK0 = 50\nC0 = 0.5\n";

/* G1(M) = M^2 at the knots -1 0 1 2 (a natural spline through them). */
static const char table[] = "-1 1\n0 0\n1 1\n2 4\n";

/* The test fails, naming the entry and the units, when the library reported
 * an error since errors was last cleared. */
static void expect_no_error(const char *entry)
{
    if (errors)
        fail_msg("%s in %s: %s", entry, units->name, last_error);
}

static void *library;
static int next_id = 100; /* a new element for every call: set-up reads the units */

static int load(void **state)
{
    (void)state;
    library = dlopen(USRSUB_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (library == NULL)
        fail_msg("%s", dlerror());
    strings[0] = test_write_file("units.gbs", gbs);
    strings[1] = test_write_file("units.gbi", gbi);
    strings[2] = test_write_file("units.gfj", gfj);
    strings[3] = test_write_file("units_rubber.gbs", rubber_gbs);
    strings[4] = test_write_file("units.tbl", table);
    return 0;
}

static int unload(void **state)
{
    (void)state;
    dlclose(library);
    return 0;
}

/* A FIESUB entry at disp, velo (model units). */
static void field(const char *entry, double string_id, const double disp[6],
                  const double velo[6], double F[6], double dfd[36], double dfv[36])
{
    usrsub_fiesub_fn *fn = (usrsub_fiesub_fn *)dlsym(library, entry);
    assert_non_null(fn);
    int id = next_id++, npar = 1, flag = 0;
    double t = 0.0, par[1] = {string_id}, d[6], v[6];
    memcpy(d, disp, sizeof d);
    memcpy(v, velo, sizeof v);
    errors = 0;
    fn(&id, &t, par, &npar, d, v, &flag, &flag, F, dfd, dfv);
    expect_no_error(entry);
}

/* L, F, T: the sizes of the model's length, force and time units in mm, N, s. */
static void scales_of(const unit_system *u, double *L, double *F, double *T)
{
    *L = u->exists ? u->length / 1e-3 : 1.0;
    *F = u->exists ? u->force : 1.0;
    *T = u->exists ? u->time : 1.0;
}

static const unit_system *const systems[] = {&m_kn_t_s, &mm_n_kg_ms, &cm_kgf_g_s, &no_units};

/* The bushing at x = 2 mm, vy = 50 mm/s, ax = 0.01 rad:
 *   Fx = -100 N/mm * 2 mm = -200 N;  Fy = -2 N s/mm * 50 mm/s = -100 N;
 *   Tx = -10 N mm/deg * (0.01 / DEG) deg = -5.7295779513 N mm;
 *   dFx/dx = -100 N/mm, dFy/dvy = -2 N s/mm, dTx/dax = -10/DEG N mm/rad.
 * In m, kN, s: x = 0.002, vy = 0.05 give Fx = -0.2, Fy = -0.1, Tx = -5.73e-6 kN m,
 * dFx/dx = -100 kN/m, dFy/dvy = -2 kN s/m, dTx/dax = -5.73e-4 kN m/rad. */
static void bushing_in_every_system(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof systems / sizeof systems[0]; ++k) {
        units = systems[k];
        double L, Fu, T;
        scales_of(units, &L, &Fu, &T);
        const int raw = !units->exists; /* values as written: the file's numbers */
        const double disp[6] = {2.0 / L, 0, 0, 0.01, 0, 0};
        const double velo[6] = {0, 50.0 * T / L, 0, 0, 0, 0};
        double F[6], dfd[36], dfv[36];
        field("ABM_BUSHING_FIELD", 1, disp, velo, F, dfd, dfv);
        const double tx = raw ? -10.0 * 0.01 : -10.0 * 0.01 / DEG;
        assert_close(F[0], -200.0 / Fu, 1e-12, 0);
        assert_close(F[1], -100.0 / Fu, 1e-12, 0);
        assert_close(F[3], tx / (Fu * L), 1e-12, 0);
        assert_close(dfd[0], -100.0 * L / Fu, 1e-12, 0);
        assert_close(dfv[1 + 6 * 1], -2.0 * L / (T * Fu), 1e-12, 0);
        assert_close(dfd[3 + 6 * 3], (raw ? -10.0 : -10.0 / DEG) / (Fu * L), 1e-12, 0);
    }
    /* by hand, in m, kN, tonne, s */
    units = &m_kn_t_s;
    const double disp[6] = {0.002, 0, 0, 0.01, 0, 0}, velo[6] = {0, 0.05, 0, 0, 0, 0};
    double F[6], dfd[36], dfv[36];
    field("ABM_BUSHING_FIELD", 1, disp, velo, F, dfd, dfv);
    assert_close(F[0], -0.2, 1e-12, 0);
    assert_close(F[1], -0.1, 1e-12, 0);
    assert_close(F[3], -5.729577951308232e-6, 1e-12, 0);
    assert_close(dfd[0], -100.0, 1e-12, 0);
    assert_close(dfv[7], -2.0, 1e-12, 0);
}

/* The limits at x = 3 mm (2 mm into contact, past D), vx = 10 mm/s, and
 * az = 0.05 rad = 2.8647889757 deg (1.8647889757 deg into contact):
 *   Fx = -1000 * 2^2 - 5 * 10 = -4050 N,  dFx/dx = -2 * 1000 * 2 = -4000 N/mm,
 *   dFx/dvx = -5 N s/mm;  Tz = -100 * 1.8647889757 = -186.47889757 N mm,
 *   dTz/daz = -100/DEG N mm/rad.
 * In mm, N, kg, ms: vx = 0.01 mm/ms; Fx = -4050 N, dFx/dvx = -5000 N ms/mm. */
static void limits_in_every_system(void **state)
{
    (void)state;
    for (size_t k = 0; k < 3; ++k) {
        units = systems[k];
        double L, Fu, T;
        scales_of(units, &L, &Fu, &T);
        const double disp[6] = {3.0 / L, 0, 0, 0, 0, 0.05};
        const double velo[6] = {10.0 * T / L, 0, 0, 0, 0, 0};
        double F[6], dfd[36], dfv[36];
        field("MOUNT_LIMITS_FIELD", 2, disp, velo, F, dfd, dfv);
        assert_close(F[0], -4050.0 / Fu, 1e-12, 0);
        assert_close(dfd[0], -4000.0 * L / Fu, 1e-12, 0);
        assert_close(dfv[0], -5.0 * L / (T * Fu), 1e-12, 0);
        assert_close(F[5], -100.0 * (0.05 / DEG - 1.0) / (Fu * L), 1e-12, 0);
        assert_close(dfd[5 + 6 * 5], -100.0 / DEG / (Fu * L), 1e-12, 0);
    }
    units = &mm_n_kg_ms;
    const double disp[6] = {3.0, 0, 0, 0, 0, 0.05}, velo[6] = {0.01, 0, 0, 0, 0, 0};
    double F[6], dfd[36], dfv[36];
    field("MOUNT_LIMITS_FIELD", 2, disp, velo, F, dfd, dfv);
    assert_close(F[0], -4050.0, 1e-12, 0);
    assert_close(dfv[0], -5000.0, 1e-12, 0);
    assert_close(F[5], -186.47889756541161, 1e-12, 0);
}

/* The flexible joint at x = 2 mm, ax = 0.01 rad, each block in its own units:
 *   Fx = 5 - (100 * 2 + 10 * 0.01) = -195.1 N;  Tx = -(10 * 2 + 1000 * 0.01) = -30 N mm;
 *   Tz = 7 N mm;  dFx/dx = -100 N/mm, dFx/dax = -10 N/rad, dTx/dx = -10 N mm/mm,
 *   dTx/dax = -1000 N mm/rad.
 * In cm, kgf: x = 0.2 cm; Fx = -195.1/KGF, Tx = -3/KGF kgf cm, dFx/dx = -1000/KGF kgf/cm,
 * dFx/dax = -10/KGF kgf/rad, dTx/dx = -10/KGF kgf cm/cm, dTx/dax = -100/KGF kgf cm/rad. */
static void flexible_joint_in_every_system(void **state)
{
    (void)state;
    for (size_t k = 0; k < 3; ++k) {
        units = systems[k];
        double L, Fu, T;
        scales_of(units, &L, &Fu, &T);
        const double disp[6] = {2.0 / L, 0, 0, 0.01, 0, 0}, velo[6] = {0};
        double F[6], dfd[36], dfv[36];
        field("FLEX_JOINT_FIELD", 3, disp, velo, F, dfd, dfv);
        assert_close(F[0], -195.1 / Fu, 1e-12, 0);
        assert_close(F[3], -30.0 / (Fu * L), 1e-12, 0);
        assert_close(F[5], 7.0 / (Fu * L), 1e-12, 0);
        assert_close(dfd[0 + 6 * 0], -100.0 * L / Fu, 1e-12, 0);
        assert_close(dfd[0 + 6 * 3], -10.0 / Fu, 1e-12, 0);
        assert_close(dfd[3 + 6 * 0], -10.0 / Fu, 1e-12, 0);
        assert_close(dfd[3 + 6 * 3], -1000.0 / (Fu * L), 1e-12, 0);
    }
    units = &cm_kgf_g_s;
    const double disp[6] = {0.2, 0, 0, 0.01, 0, 0}, velo[6] = {0};
    double F[6], dfd[36], dfv[36];
    field("FLEX_JOINT_FIELD", 3, disp, velo, F, dfd, dfv);
    assert_close(F[0], -195.1 / KGF, 1e-12, 0);
    assert_close(F[3], -3.0 / KGF, 1e-12, 0);
    assert_close(dfd[0], -1000.0 / KGF, 1e-12, 0);
    assert_close(dfd[3 + 6 * 3], -100.0 / KGF, 1e-12, 0);
}

/* YFOSUB with the rubber filter at dx = 2 mm, vx = 10 mm/s, state x = 1 mm:
 *   xdot = vx - R x = 10 - 20 * 1 = -10 mm/s;
 *   Fx = -100 * 2 - (50 * 1 + 0.5 * (-10)) = -245 N.
 * In mm, N, ms: vx = 0.01 mm/ms, R = 0.02 1/ms: xdot = -0.01 mm/ms.
 * In m, kN, s: dx = 0.002, vx = 0.01, x = 0.001: xdot = -0.01 m/s, Fx = -0.245 kN. */
static void state_equation_in_every_system(void **state)
{
    (void)state;
    usrsub_yfosub_fn *yfosub = (usrsub_yfosub_fn *)dlsym(library, "YFOSUB");
    assert_non_null(yfosub);
    for (size_t k = 0; k < 3; ++k) {
        units = systems[k];
        double L, Fu, T;
        scales_of(units, &L, &Fu, &T);
        int id = next_id++, npar = 2, flag = 0, nstate = 1, ninput = 12, noutpt = 6;
        double t = 0.0, par[2] = {1, 4}, states[1] = {1.0 / L}, input[12] = {0};
        input[0] = 2.0 / L;
        input[6] = 10.0 * T / L;
        double stated[1], output[6];
        errors = 0;
        yfosub(&id, &t, par, &npar, &flag, &flag, &nstate, states, &ninput, input, &noutpt,
               stated, output);
        expect_no_error("YFOSUB");
        assert_close(stated[0], -10.0 * T / L, 1e-12, 0);
        assert_close(output[0], -245.0 / Fu, 1e-12, 0);
    }
}

/* COUSUB USER(4, table, 2, 1, -3): phi = 2 G1(M1) - 3 M2 with G1 the table's
 * spline through M^2's knots: at M = (1, 0.5), phi = 2 * 1 - 1.5 = 0.5 in every
 * system: a joint's coordinate has no unit the table could be converted from. */
static void coupler_table_is_not_converted(void **state)
{
    (void)state;
    usrsub_coupler_fn *cousub = (usrsub_coupler_fn *)dlsym(library, "COUSUB");
    assert_non_null(cousub);
    for (size_t k = 0; k < sizeof systems / sizeof systems[0]; ++k) {
        units = systems[k];
        int id = next_id++, npar = 5, ndisp = 2, flag = 0;
        double t = 0.0, par[5] = {4, 5, 2, 1, -3}, disp[2] = {1.0, 0.5}, phi = 0.0;
        errors = 0;
        cousub(&id, &t, par, &npar, disp, &ndisp, &flag, &phi);
        expect_no_error("COUSUB");
        assert_close(phi, 0.5, 1e-14, 1e-14);
    }
}

/* A host whose sizes are not positive and finite: an error naming the size,
 * zero outputs; one case per slot of the layout. */
static void a_host_with_bad_sizes_is_named(void **state)
{
    (void)state;
    static const unit_system bad[] = {
        {"NaN time", 1, NAN, 1.0, 1.0, 1.0, "S  M  N  KG "},
        {"zero length", 1, 1.0, 0.0, 1.0, 1.0, "S  M  N  KG "},
        {"infinite force", 1, 1.0, 1.0, INFINITY, 1.0, "S  M  N  KG "},
        {"negative mass", 1, 1.0, 1.0, 1.0, -1.0, "S  M  N  KG "}};
    static const char *const named[] = {"time nan s", "length 0 m", "force inf N", "mass -1 kg"};
    usrsub_fiesub_fn *fn = (usrsub_fiesub_fn *)dlsym(library, "ABM_BUSHING_FIELD");
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        units = &bad[k];
        int id = next_id++, npar = 1, flag = 0;
        double t = 0.0, par[1] = {1}, d[6] = {1, 0, 0, 0, 0, 0}, v[6] = {0}, F[6], dfd[36],
               dfv[36];
        errors = 0;
        fn(&id, &t, par, &npar, d, v, &flag, &flag, F, dfd, dfv);
        assert_int_equal(errors, 1);
        assert_contains(last_error, "c_gtunts", "not positive and finite", named[k]);
        for (int i = 0; i < 6; ++i)
            assert_true(F[i] == 0.0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bushing_in_every_system),
        cmocka_unit_test(limits_in_every_system),
        cmocka_unit_test(flexible_joint_in_every_system),
        cmocka_unit_test(state_equation_in_every_system),
        cmocka_unit_test(coupler_table_is_not_converted),
        cmocka_unit_test(a_host_with_bad_sizes_is_named),
    };
    return cmocka_run_group_tests(tests, load, unload);
}
