/*
 * Fuzz target: every entry of the library (COUSUB, COUXX, COUXX2, GFOSUB,
 * FIESUB and the named ones) on arbitrary USER lists, element ids, joint
 * counts and states, with the harness as host and a model whose strings name
 * the example property files. The bytes are read as a stream of tagged
 * values, so that small integers, string ids, marker ids, NaN, infinities
 * and huge counts all turn up. Every output must be finite: a NaN or an
 * infinity passed on is a crash here.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "element_cache.h"
#include "host/call.h" /* the harness as host (entries/host.h is the library's adapter) */
#include "model/model.h"
#include "property_cache.h"
#include "frames/frames.h"
#include "usrsub/solver_abi.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

static hx_model *model;
static hx_frames state;
static hx_messages messages;
static hx_call call;

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    static const char text[] =
        "<MotionSolve><Model>\n"
        "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
        "<Reference_String id=\"1\" string=\"" EXAMPLES_DIR "/bench_bushing.gbs\"/>\n"
        "<Reference_String id=\"2\" string=\"" EXAMPLES_DIR "/mount_limits.gbi\"/>\n"
        "<Reference_String id=\"3\" string=\"" EXAMPLES_DIR "/flex_coupled.gfj\"/>\n"
        "<Reference_String id=\"4\" string=\"" EXAMPLES_DIR "/steering_ratio.tbl\"/>\n"
        "<Reference_String id=\"5\" string=\"" EXAMPLES_DIR "/coupled_isotropic.gbs\"/>\n"
        "<Reference_String id=\"6\" string=\"" EXAMPLES_DIR "/bevel_gears.xml\"/>\n"
        "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\""
        " v_ic_x=\"3\" w_ic_z=\"0.5\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1.5\" pos_y=\"-0.5\"/>\n"
        "</Model></MotionSolve>\n";
    hx_message msg;
    model = hx_model_parse(text, sizeof text - 1, "/tmp/fuzz_host.xml", NULL, &msg);
    if (model == NULL) {
        fprintf(stderr, "fuzz_user_lists: %s\n", msg.text);
        abort();
    }
    if (hx_frames_init(&state, model) != 0)
        abort();
    hx_messages_init(&messages, NULL);
    hx_call_init(&call, "fuzzed element", 0, "entry", model, &state, &messages, 0, NULL);
    hx_host_bind(&call);
    return 0;
}

typedef struct stream {
    const uint8_t *data;
    size_t size, at;
} stream;

static uint8_t next_byte(stream *s)
{
    return s->at < s->size ? s->data[s->at++] : 0;
}

/* A tagged value: mostly the numbers USER lists hold, sometimes anything. */
static double next_value(stream *s)
{
    const uint8_t tag = next_byte(s);
    switch (tag % 8) {
    case 0: return (double)(next_byte(s) % 8);          /* codes, counts */
    case 1: return (double)(1 + next_byte(s) % 6);      /* string ids */
    case 2: return next_byte(s) % 2 ? 10.0 : 20.0;       /* marker ids */
    case 3: return ((int8_t)next_byte(s)) / 16.0;        /* small reals */
    case 4: {
        static const double odd[] = {NAN, INFINITY, -INFINITY, 1e308, -1e308, 4.9e-324,
                                     2147483648.0, 1e9, -1.0, 0.5};
        return odd[next_byte(s) % 10];
    }
    default: {
        double v = 0.0;
        uint8_t bytes[8];
        for (int k = 0; k < 8; ++k)
            bytes[k] = next_byte(s);
        memcpy(&v, bytes, sizeof v);
        return v;
    }
    }
}

static void check(const double *out, int n, const char *entry)
{
    for (int k = 0; k < n; ++k)
        if (!isfinite(out[k])) {
            fprintf(stderr, "%s passed on a non-finite output %d: %g\n", entry, k, out[k]);
            abort();
        }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static long inputs;
    if (++inputs % 512 == 0) { /* each new USER list is a new set-up: start afresh */
        usrsub_element_cache_clear();
        usrsub_property_cache_clear();
    }
    stream s = {data, size, 0};
    const int entry = next_byte(&s) % 11;
    int id = next_byte(&s) % 16, ndisp = next_byte(&s) % 5, npar = next_byte(&s) % 40;
    double par[40], disp[6], velo[6];
    for (int k = 0; k < npar; ++k)
        par[k] = next_value(&s);
    for (int k = 0; k < 6; ++k)
        disp[k] = next_value(&s), velo[k] = next_value(&s);
    double out[81], t = 0.0;
    int dflag = 0, iflag = next_byte(&s) % 2;
    switch (entry) {
    case 0: COUSUB(&id, &t, par, &npar, disp, &ndisp, &iflag, out); check(out, 1, "COUSUB"); break;
    case 1:
        COUXX(&id, &t, par, &npar, disp, &ndisp, &iflag, out);
        check(out, ndisp >= 2 && ndisp <= 3 ? ndisp : 0, "COUXX");
        break;
    case 2:
        COUXX2(&id, &t, par, &npar, disp, &ndisp, &iflag, out);
        check(out, ndisp >= 2 && ndisp <= 3 ? ndisp * ndisp : 0, "COUXX2");
        break;
    case 3: GFOSUB(&id, &t, par, &npar, &dflag, &iflag, out); check(out, 6, "GFOSUB"); break;
    case 4: ABM_BUSHING(&id, &t, par, &npar, &dflag, &iflag, out); check(out, 6, "ABM_BUSHING"); break;
    case 5: MOUNT_LIMITS(&id, &t, par, &npar, &dflag, &iflag, out); check(out, 6, "MOUNT_LIMITS"); break;
    case 6: FLEX_JOINT(&id, &t, par, &npar, &dflag, &iflag, out); check(out, 6, "FLEX_JOINT"); break;
    case 7:
        FIESUB(&id, &t, par, &npar, disp, velo, &dflag, &iflag, out, out + 6, out + 42);
        check(out, 78, "FIESUB");
        break;
    case 8:
        ABM_BUSHING_FIELD(&id, &t, par, &npar, disp, velo, &dflag, &iflag, out, out + 6, out + 42);
        check(out, 78, "ABM_BUSHING_FIELD");
        break;
    case 9:
        MOUNT_LIMITS_FIELD(&id, &t, par, &npar, disp, velo, &dflag, &iflag, out, out + 6, out + 42);
        check(out, 78, "MOUNT_LIMITS_FIELD");
        break;
    default:
        FLEX_JOINT_FIELD(&id, &t, par, &npar, disp, velo, &dflag, &iflag, out, out + 6, out + 42);
        check(out, 78, "FLEX_JOINT_FIELD");
        break;
    }
    return 0;
}
