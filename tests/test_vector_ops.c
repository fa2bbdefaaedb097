/*
 * The serial vector's operations the harness gives CVODE and ARKODE
 * (sim/ode/vector_ops.h) against SUNDIALS' own, fused operations enabled:
 * every operation on every length from 0 to 13 (loops' tails) and the
 * 64-body chain's 834, with values of every sign and size, with each
 * coefficient SUNDIALS treats apart (1, -1, a = b, a = -b) and the result in
 * place of each argument; equal bit for bit, the norm to rounding (it sums in
 * another order). Installed on one vector, they are every clone's.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sim/ode/vector_ops.h"
#include "test_support.h"

#define LENGTHS 15
static const long lengths[LENGTHS] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 834};
#define TERMS 5
#define VECTORS 8 /* the last a weight */
#define WEIGHT (VECTORS - 1)

typedef struct pair {
    N_Vector theirs[VECTORS], ours[VECTORS]; /* the same values in each */
} pair;

static unsigned seed = 12345u;

static double draw(long i)
{
    seed = seed * 1664525u + 1013904223u;
    return ((double)(seed >> 8) / 16777216.0 - 0.5) * pow(10.0, (double)(i % 7) - 3.0);
}

/* The operations vector_ops.c installs, as they stand in a table. */
#define OPS 14
static void installed_ops(const N_Vector_Ops o, const void *out[OPS])
{
    const void *ops[OPS] = {o->nvlinearsum, o->nvconst,     o->nvprod,     o->nvdiv,
                            o->nvscale,     o->nvabs,       o->nvinv,      o->nvaddconst,
                            o->nvmaxnorm,   o->nvwrmsnorm,  o->nvmin,      o->nvcompare,
                            o->nvlinearcombination, o->nvscaleaddmulti};
    memcpy(out, ops, sizeof ops);
}

static void open_pair(pair *p, SUNContext context, long n)
{
    N_Vector plain = N_VNew_Serial(n, context), template = N_VNew_Serial(n, context);
    assert_non_null(plain), assert_non_null(template);
    assert_int_equal(N_VEnableFusedOps_Serial(plain, SUNTRUE), 0);
    hx_vector_ops_install(template);
    for (int k = 0; k < VECTORS; ++k) {
        p->theirs[k] = N_VClone(plain);
        p->ours[k] = N_VClone(template);
        assert_non_null(p->theirs[k]), assert_non_null(p->ours[k]);
        /* every operation installed, in every clone */
        const void *ours[OPS], *installed[OPS], *theirs[OPS];
        installed_ops(p->ours[k]->ops, ours);
        installed_ops(template->ops, installed);
        installed_ops(plain->ops, theirs);
        for (int op = 0; op < OPS; ++op) {
            assert_true(ours[op] == installed[op]);
            if (ours[op] == theirs[op])
                fail_msg("operation %d of the table is still SUNDIALS' own", op);
        }
    }
    N_VDestroy(plain), N_VDestroy(template);
}

/* Fresh values, the same in both (positive where a test needs a weight). */
static void fill(pair *p, long n)
{
    for (int k = 0; k < VECTORS; ++k)
        for (long i = 0; i < n; ++i) {
            double v = draw(i);
            if (k == WEIGHT)
                v = 1.0 / (1e-5 * fabs(v) + 1e-8 * (double)(1 + i % 3));
            else if (i % 11 == 3)
                v = 0.0;
            NV_Ith_S(p->theirs[k], i) = NV_Ith_S(p->ours[k], i) = v;
        }
}

static void close_pair(pair *p)
{
    for (int k = 0; k < VECTORS; ++k)
        N_VDestroy(p->theirs[k]), N_VDestroy(p->ours[k]);
}

/* Every vector of the pair equal bit for bit. */
static void assert_same(const pair *p, long n, const char *what)
{
    for (int k = 0; k < VECTORS; ++k)
        if (n > 0 && memcmp(NV_DATA_S(p->theirs[k]), NV_DATA_S(p->ours[k]),
                            sizeof(double) * (size_t)n) != 0)
            fail_msg("%s, length %ld: vector %d differs from SUNDIALS' own", what, n, k);
}

static void linear_sums(pair *p, long n)
{
    static const double ab[][2] = {{1, 1},     {1, -1},     {-1, 1},   {1, 2.5},  {2.5, 1},
                                   {-1, 0.3},  {0.3, -1},   {0.7, 0.7}, {0.7, -0.7}, {0.3, 1.9},
                                   {-1, -1},   {0, 1}};
    for (size_t c = 0; c < sizeof ab / sizeof ab[0]; ++c)
        for (int into = 0; into < 3; ++into) { /* z apart, z = x, z = y */
            fill(p, n);
            const int z = into == 0 ? 2 : into - 1;
            N_VLinearSum(ab[c][0], p->theirs[0], ab[c][1], p->theirs[1], p->theirs[z]);
            N_VLinearSum(ab[c][0], p->ours[0], ab[c][1], p->ours[1], p->ours[z]);
            char what[80];
            snprintf(what, sizeof what, "linear sum %g x + %g y into %d", ab[c][0], ab[c][1], z);
            assert_same(p, n, what);
        }
}

static void element_wise(pair *p, long n)
{
    static const double factors[] = {1.0, -1.0, 2.5, 0.0};
    for (int into = 0; into < 2; ++into) { /* z apart, z = x */
        const int z = into == 0 ? 2 : 0;
        for (size_t c = 0; c < sizeof factors / sizeof factors[0]; ++c) {
            fill(p, n);
            N_VScale(factors[c], p->theirs[0], p->theirs[z]);
            N_VScale(factors[c], p->ours[0], p->ours[z]);
            assert_same(p, n, "scale");
        }
        fill(p, n);
        N_VConst(0.125, p->theirs[z]), N_VConst(0.125, p->ours[z]);
        assert_same(p, n, "const");
        fill(p, n);
        N_VProd(p->theirs[0], p->theirs[1], p->theirs[z]);
        N_VProd(p->ours[0], p->ours[1], p->ours[z]);
        assert_same(p, n, "product");
        fill(p, n);
        N_VDiv(p->theirs[0], p->theirs[WEIGHT], p->theirs[z]);
        N_VDiv(p->ours[0], p->ours[WEIGHT], p->ours[z]);
        assert_same(p, n, "quotient");
        fill(p, n);
        N_VAbs(p->theirs[0], p->theirs[z]), N_VAbs(p->ours[0], p->ours[z]);
        assert_same(p, n, "absolute value");
        fill(p, n);
        N_VInv(p->theirs[WEIGHT], p->theirs[into == 0 ? 2 : WEIGHT]);
        N_VInv(p->ours[WEIGHT], p->ours[into == 0 ? 2 : WEIGHT]);
        assert_same(p, n, "inverse");
        fill(p, n);
        N_VAddConst(p->theirs[0], -0.375, p->theirs[z]);
        N_VAddConst(p->ours[0], -0.375, p->ours[z]);
        assert_same(p, n, "add a constant");
        /* the threshold apart from every value, at zero (values hold zeros),
         * and at a value itself: >= and > differ only there */
        for (int t = 0; t < 3; ++t) {
            fill(p, n);
            const double c = t == 0 ? 0.01 : t == 1 || n == 0 ? 0.0 : fabs(NV_Ith_S(p->ours[0], n / 2));
            N_VCompare(c, p->theirs[0], p->theirs[z]);
            N_VCompare(c, p->ours[0], p->ours[z]);
            assert_same(p, n, "compare");
        }
    }
}

static void reductions(pair *p, long n)
{
    fill(p, n);
    if (n == 0)
        return; /* SUNDIALS' norm divides by n; its minimum reads x[0] */
    assert_true(N_VMaxNorm(p->ours[0]) == N_VMaxNorm(p->theirs[0]));
    assert_true(N_VMin(p->ours[0]) == N_VMin(p->theirs[0]));
    const double ours = N_VWrmsNorm(p->ours[0], p->ours[WEIGHT]);
    const double theirs = N_VWrmsNorm(p->theirs[0], p->theirs[WEIGHT]);
    assert_close(ours, theirs, 1e-14, 0);
    assert_true(ours == hx_wrms_norm(NV_DATA_S(p->ours[0]), NV_DATA_S(p->ours[WEIGHT]), n));
}

static void fused(pair *p, long n)
{
    /* coefficients SUNDIALS treats apart: 1 and -1, and a = b, a = -b away from them */
    static const double sets[4][TERMS] = {{1.0, -1.0, 0.3, 2.5, -0.7},
                                          {0.9, 1.0, -1.0, 0.4, 0.4},
                                          {0.7, 0.7, 0.7, -0.7, 1.0},
                                          {0.7, -0.7, 2.0, 1.0, -1.0}};
    for (int set = 0; set < 4; ++set)
        for (int count = 1; count <= TERMS; ++count)
            for (int into = -1; into < count; ++into) { /* z apart, or each of the terms */
                fill(p, n);
                const int z = into < 0 ? TERMS : into;
                N_VLinearCombination(count, (double *)sets[set], p->theirs, p->theirs[z]);
                N_VLinearCombination(count, (double *)sets[set], p->ours, p->ours[z]);
                char what[96];
                snprintf(what, sizeof what, "linear combination of %d (set %d) into %d", count,
                         set, z);
                assert_same(p, n, what);
            }
    for (int set = 0; set < 4; ++set)
        for (int count = 1; count <= 3; ++count)
            for (int in_place = 0; in_place < 2; ++in_place) {
                fill(p, n);
                N_Vector *Yt = p->theirs + 1, *Yo = p->ours + 1;
                N_Vector *Zt = in_place ? Yt : p->theirs + 1 + count;
                N_Vector *Zo = in_place ? Yo : p->ours + 1 + count;
                N_VScaleAddMulti(count, (double *)sets[set], p->theirs[0], Yt, Zt);
                N_VScaleAddMulti(count, (double *)sets[set], p->ours[0], Yo, Zo);
                char what[96];
                snprintf(what, sizeof what, "scale-add of %d (set %d)%s", count, set,
                         in_place ? " in place" : "");
                assert_same(p, n, what);
            }
    /* no terms: refused, as SUNDIALS refuses them */
    double one = 1.0;
    assert_int_equal(N_VLinearCombination(0, &one, p->ours, p->ours[0]),
                     N_VLinearCombination(0, &one, p->theirs, p->theirs[0]));
    assert_int_equal(N_VScaleAddMulti(0, &one, p->ours[0], p->ours + 1, p->ours + 1),
                     N_VScaleAddMulti(0, &one, p->theirs[0], p->theirs + 1, p->theirs + 1));
}

static void every_operation_is_sundials_own(void **state)
{
    (void)state;
    SUNContext context;
    assert_int_equal(SUNContext_Create(NULL, &context), 0);
    for (int l = 0; l < LENGTHS; ++l) {
        pair p;
        open_pair(&p, context, lengths[l]);
        linear_sums(&p, lengths[l]);
        element_wise(&p, lengths[l]);
        reductions(&p, lengths[l]);
        fused(&p, lengths[l]);
        close_pair(&p);
    }
    SUNContext_Free(&context);
}

/* The norm by hand: sqrt((6^2 + 2^2) / 2), and 0 of nothing. */
static void the_norm_by_hand(void **state)
{
    (void)state;
    const double three_four[2] = {3.0, 4.0}, halves[2] = {2.0, 0.5};
    assert_close(hx_wrms_norm(three_four, halves, 2), sqrt((36.0 + 4.0) / 2.0), 1e-15, 0);
    assert_close(hx_wrms_norm(three_four, halves, 0), 0.0, 0, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_norm_by_hand),
        cmocka_unit_test(every_operation_is_sundials_own),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
