/*
 * Every bundled example's dataset twin (harness/examples/NAME.adm, written
 * by scripts/adm_twins.py) against its XML (docs/interface.md §9.10): the
 * two readers give equal models, field by field, the markers' frames and
 * every number to the bit; and a short run of each gives the same CSV, byte
 * for byte. A twin that drifts from its XML fails here.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr/expr.h"
#include "model/model.h"
#include "sim_support.h"
#include "test_support.h"

#define SAME(field) assert_memory_equal(&(a)->field, &(b)->field, sizeof((a)->field))

static void same_text(const char *a, const char *b, const char *what)
{
    if ((a == NULL) != (b == NULL) || (a != NULL && strcmp(a, b) != 0))
        fail_msg("%s: \"%s\" against \"%s\"", what, a ? a : "(none)", b ? b : "(none)");
}

static void same_user(const hx_user_call *a, const hx_user_call *b)
{
    same_text(a->dll_name, b->dll_name, "dll_name");
    same_text(a->fnc_name, b->fnc_name, "fnc_name");
    same_text(a->der1_name, b->der1_name, "der1_name");
    same_text(a->der2_name, b->der2_name, "der2_name");
    same_text(a->der3_name, b->der3_name, "der3_name");
    same_text(a->der4_name, b->der4_name, "der4_name");
    assert_int_equal(a->npar, b->npar);
    if (a->npar > 0)
        assert_memory_equal(a->par, b->par, sizeof(double) * (size_t)a->npar);
}

/* Every field that matters, to the bit (memory equal). */
/* Two loads' expressions the same program: both absent, or the same ops,
 * inputs and stack, and the same constant when they are one. */
static void same_program(const hx_expr_program *a, const hx_expr_program *b)
{
    assert_int_equal(a == NULL, b == NULL);
    if (a == NULL)
        return;
    assert_int_equal(hx_expr_op_count(a), hx_expr_op_count(b));
    assert_int_equal(hx_expr_input_count(a), hx_expr_input_count(b));
    assert_int_equal(hx_expr_depth(a), hx_expr_depth(b));
    double x = 0.0, y = 0.0;
    assert_int_equal(hx_expr_constant(a, &x), hx_expr_constant(b, &y));
    assert_memory_equal(&x, &y, sizeof x);
}

static void same_model(const hx_model *a, const hx_model *b)
{
    SAME(has_units);
    SAME(unit_scales);
    SAME(gravity);
    assert_int_equal(a->nunsimulated, 0);
    assert_int_equal(b->nunsimulated, 0);
    assert_int_equal(a->nbodies, b->nbodies);
    assert_int_equal(a->ground, b->ground);
    for (int k = 0; k < a->nbodies; ++k) {
        const hx_body *x = &a->bodies[k], *y = &b->bodies[k];
        assert_int_equal(x->id, y->id);
        assert_int_equal(x->is_ground, y->is_ground);
        assert_int_equal(x->cg_marker, y->cg_marker);
        assert_int_equal(x->joint, y->joint);
        assert_memory_equal(&x->mass, &y->mass, sizeof x->mass);
        assert_memory_equal(x->inertia, y->inertia, sizeof x->inertia);
        assert_memory_equal(x->p0, y->p0, sizeof x->p0);
        assert_memory_equal(x->R0, y->R0, sizeof x->R0);
        assert_memory_equal(x->v0, y->v0, sizeof x->v0);
        assert_memory_equal(x->w0, y->w0, sizeof x->w0);
    }
    assert_int_equal(a->nmarkers, b->nmarkers);
    for (int k = 0; k < a->nmarkers; ++k) {
        const hx_marker *x = &a->markers[k], *y = &b->markers[k];
        assert_int_equal(x->id, y->id);
        assert_int_equal(x->body, y->body);
        assert_int_equal(x->tracked, y->tracked);
        assert_int_equal(x->local_axes, y->local_axes);
        assert_int_equal(x->at_body_origin, y->at_body_origin);
        assert_memory_equal(x->pos0, y->pos0, sizeof x->pos0);
        assert_memory_equal(x->R0, y->R0, sizeof x->R0);
        assert_memory_equal(x->r_local, y->r_local, sizeof x->r_local);
        assert_memory_equal(x->R_local, y->R_local, sizeof x->R_local);
    }
    assert_int_equal(a->njoints, b->njoints);
    for (int k = 0; k < a->njoints; ++k) { /* all but the line */
        assert_int_equal(a->joints[k].id, b->joints[k].id);
        assert_int_equal(a->joints[k].type, b->joints[k].type);
        assert_int_equal(a->joints[k].i_marker, b->joints[k].i_marker);
        assert_int_equal(a->joints[k].j_marker, b->joints[k].j_marker);
    }
    assert_int_equal(a->ncouplers, b->ncouplers);
    for (int k = 0; k < a->ncouplers; ++k) {
        const hx_coupler *x = &a->couplers[k], *y = &b->couplers[k];
        assert_int_equal(x->id, y->id);
        assert_int_equal(x->njoints, y->njoints);
        assert_memory_equal(x->joint, y->joint, sizeof x->joint);
        assert_memory_equal(x->coefficients, y->coefficients, sizeof x->coefficients);
        assert_int_equal(x->is_user, y->is_user);
        same_user(&x->user, &y->user);
    }
    assert_int_equal(a->nforces, b->nforces);
    for (int k = 0; k < a->nforces; ++k) {
        const hx_force *x = &a->forces[k], *y = &b->forces[k];
        assert_int_equal(x->id, y->id);
        assert_int_equal(x->interface, y->interface);
        assert_int_equal(x->part, y->part);
        assert_int_equal(x->one_body, y->one_body);
        assert_int_equal(x->i_marker, y->i_marker);
        assert_int_equal(x->j_marker, y->j_marker);
        assert_int_equal(x->ref_marker, y->ref_marker);
        same_user(&x->user, &y->user);
    }
    assert_int_equal(a->nloads, b->nloads);
    for (int k = 0; k < a->nloads; ++k) {
        const hx_load *x = &a->loads[k], *y = &b->loads[k];
        assert_int_equal(x->id, y->id);
        assert_int_equal(x->kind, y->kind);
        assert_int_equal(x->i_marker, y->i_marker);
        assert_int_equal(x->j_marker, y->j_marker);
        assert_int_equal(x->ref_marker, y->ref_marker);
        assert_int_equal(x->action_only, y->action_only);
        for (int i = 0; i < 3; ++i) {
            same_program(x->force[i], y->force[i]);
            same_program(x->torque[i], y->torque[i]);
        }
        same_program(x->value, y->value);
    }
    assert_int_equal(a->nstrings, b->nstrings);
    for (int k = 0; k < a->nstrings; ++k) {
        assert_int_equal(a->strings[k].id, b->strings[k].id);
        assert_string_equal(a->strings[k].text, b->strings[k].text);
    }
    assert_int_equal(a->nvariables, b->nvariables);
    for (int k = 0; k < a->nvariables; ++k)
        assert_memory_equal(&a->variables[k].id, &b->variables[k].id,
                            offsetof(hx_variable, line) - offsetof(hx_variable, id));
    assert_int_equal(a->narrays, b->narrays);
    for (int k = 0; k < a->narrays; ++k) {
        const hx_array *x = &a->arrays[k], *y = &b->arrays[k];
        assert_int_equal(x->id, y->id);
        assert_int_equal(x->type, y->type);
        assert_int_equal(x->count, y->count);
        assert_int_equal(x->numbers != NULL, y->numbers != NULL);
        if (x->numbers != NULL && x->count > 0)
            assert_memory_equal(x->numbers, y->numbers, sizeof(double) * (size_t)x->count);
        if (x->variables != NULL && x->count > 0)
            assert_memory_equal(x->variables, y->variables, sizeof(int) * (size_t)x->count);
    }
    assert_int_equal(a->nstateeqns, b->nstateeqns);
    for (int k = 0; k < a->nstateeqns; ++k) {
        const hx_stateeqn *x = &a->stateeqns[k], *y = &b->stateeqns[k];
        assert_int_equal(x->id, y->id);
        assert_int_equal(x->i_marker, y->i_marker);
        assert_int_equal(x->j_marker, y->j_marker);
        assert_int_equal(x->ref_marker, y->ref_marker);
        assert_int_equal(x->nstate, y->nstate);
        assert_int_equal(x->ninput, y->ninput);
        assert_int_equal(x->static_hold, y->static_hold);
        assert_memory_equal(x->initial, y->initial, sizeof(double) * (size_t)x->nstate);
        if (x->ninput > 0)
            assert_memory_equal(x->inputs, y->inputs, sizeof(int) * (size_t)x->ninput);
        same_user(&x->user, &y->user);
    }
    assert_int_equal(a->nroutines, b->nroutines);
    for (int k = 0; k < a->nroutines; ++k) {
        const hx_routine *x = &a->routines[k], *y = &b->routines[k];
        assert_int_equal(x->id, y->id);
        assert_int_equal(x->kind, y->kind);
        assert_int_equal(x->joint, y->joint);
        assert_int_equal(x->val_type, y->val_type);
        assert_memory_equal(x->ic, y->ic, sizeof x->ic);
        same_user(&x->user, &y->user);
    }
    assert_int_equal(a->ngcons, b->ngcons);
    for (int k = 0; k < a->ngcons; ++k) {
        assert_int_equal(a->gcons[k].id, b->gcons[k].id);
        assert_int_equal(a->gcons[k].i_marker, b->gcons[k].i_marker);
        assert_int_equal(hx_expr_op_count(a->gcons[k].program), hx_expr_op_count(b->gcons[k].program));
    }
    assert_int_equal(a->nsplines, b->nsplines);
    for (int k = 0; k < a->nsplines; ++k) {
        const hx_spline *x = &a->splines[k], *y = &b->splines[k];
        assert_int_equal(x->nx, y->nx);
        assert_memory_equal(x->x, y->x, sizeof(double) * (size_t)x->nx);
        assert_memory_equal(x->y, y->y, sizeof(double) * (size_t)x->nx);
        assert_int_equal(x->linear_extrapolate, y->linear_extrapolate);
    }
}

/* The bundled examples' names (NAME.xml), sorted. */
static int list_examples(char names[][64], int max)
{
    DIR *dir = opendir(EXAMPLES_DIR);
    assert_non_null(dir);
    int n = 0;
    for (struct dirent *d; (d = readdir(dir)) != NULL && n < max;) {
        const size_t len = strlen(d->d_name);
        if (len > 4 && len < 60 && strcmp(d->d_name + len - 4, ".xml") == 0)
            snprintf(names[n++], 64, "%.*s", (int)(len - 4), d->d_name);
    }
    closedir(dir);
    qsort(names, (size_t)n, 64, (int (*)(const void *, const void *))strcmp);
    return n;
}

static hx_model *read_example(const char *name, const char *extension)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s.%s", EXAMPLES_DIR, name, extension);
    hx_message msg;
    hx_model *m = hx_model_read(path, NULL, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    return m;
}

static void every_twin_reads_into_its_xmls_model(void **state)
{
    (void)state;
    char names[64][64];
    const int n = list_examples(names, 64);
    assert_true(n >= 30);
    for (int k = 0; k < n; ++k) {
        printf("  %s\n", names[k]);
        fflush(stdout);
        hx_model *a = read_example(names[k], "xml"), *b = read_example(names[k], "adm");
        same_model(a, b);
        hx_model_free(a);
        hx_model_free(b);
    }
}

static char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        fail_msg("cannot open %s", path);
    fseek(f, 0, SEEK_END);
    const long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)size + 1);
    assert_non_null(text);
    *n = fread(text, 1, (size_t)size, f);
    fclose(f);
    return text;
}

static void every_twin_runs_as_its_xml(void **state)
{
    (void)state;
    char names[64][64];
    const int n = list_examples(names, 64);
    for (int k = 0; k < n; ++k) {
        char model[2][4224], csv[2][4224]; /* the temporary folder and a name */
        const char *const ext[2] = {"xml", "adm"};
        char *text[2];
        size_t size[2];
        for (int i = 0; i < 2; ++i) {
            snprintf(model[i], sizeof model[i], "%s/%s.%s", EXAMPLES_DIR, names[k], ext[i]);
            snprintf(csv[i], sizeof csv[i], "%s/%s_%s.csv", test_temp_dir(), names[k], ext[i]);
            /* the model alone: a bundled dataset's command file is not the XML's */
            const char *const args[] = {"--end", "0.01", "--no-acf", "--quiet", NULL};
            if (sim_run_csv(model[i], csv[i], args) != 0)
                fail_msg("run %s failed", model[i]);
            text[i] = slurp(csv[i], &size[i]);
        }
        if (size[0] != size[1] || memcmp(text[0], text[1], size[0]) != 0)
            fail_msg("%s: the dataset's run differs from the XML's", names[k]);
        assert_true(size[0] > 100);
        free(text[0]);
        free(text[1]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_twin_reads_into_its_xmls_model),
        cmocka_unit_test(every_twin_runs_as_its_xml),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
