/* C test of the wrc C interface (driven by ffi/tests/c_api.rs, which builds the tables, compiles
 * this file with `cc -std=c11 -Wall -Wextra -Werror` against libwrc_ffi.a and compares the
 * output with the Rust API's bit for bit).
 *
 * Usage: step_test TABLE_F64 TABLE_F32 TABLE_OVER_CAPACITY_F64
 *
 * Prints, one line each:
 *   info <value_bytes> <n_dy> <n_load> <slots> <strips> <side> <total_bytes>
 *   f64 <i> <status> <vertical_approach> <vertical_load> <n_slots> then per used slot 15 values
 *   f32 <i> ... (same in f32)
 *   g64 <i> ..., g32 <i> ... the time loop's step (wrc_step_from_*) from the cold step's output
 * for the S1002/UIC60 lateral-shift sweep dy = -8 + 0.5 i mm, i = 0..24 (F_z 83.3 kN, mu 0.3,
 * 100 km/h nominal rolling, R0 460 mm); every value as the hex of its IEEE bits (uint64 for
 * f64, uint32 for f32) so the comparison is exact. Then checks the bad-input status codes
 * itself and prints "bad <name> <status>" per case; exits 1 on the first unexpected code. */
#include "wrc.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;

static uint8_t *read_file(const char *path, size_t *len) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "cannot open %s\n", path);
        exit(2);
    }
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    uint8_t *b = malloc((size_t)n);
    if (!b || fread(b, 1, (size_t)n, f) != (size_t)n) {
        fprintf(stderr, "cannot read %s\n", path);
        exit(2);
    }
    fclose(f);
    *len = (size_t)n;
    return b;
}

static uint64_t bits64(double x) {
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static uint32_t bits32(float x) {
    uint32_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static void expect(const char *name, wrc_status got, wrc_status want) {
    printf("bad %s %d\n", name, (int)got);
    if (got != want) {
        fprintf(stderr, "%s: got %s, expected %s\n", name, wrc_status_name((int32_t)got),
                wrc_status_name((int32_t)want));
        failures++;
    }
}

static wrc_step_input_f64 input_f64(double dy) {
    wrc_step_input_f64 in;
    memset(&in, 0, sizeof in);
    in.dy = dy;
    in.fz = 83300.0;
    in.speed = 100.0 / 3.6 * 1000.0;
    in.pitch_rate = in.speed / 460.0;
    in.mu = 0.3;
    in.normalisation = 0;
    return in;
}

static wrc_step_input_f32 input_f32(double dy) {
    wrc_step_input_f32 in;
    memset(&in, 0, sizeof in);
    in.dy = (float)dy;
    in.fz = 83300.0f;
    in.speed = (float)(100.0 / 3.6 * 1000.0);
    in.pitch_rate = in.speed / 460.0f;
    in.mu = 0.3f;
    in.normalisation = 0;
    return in;
}

static void print_slot64(const wrc_slot_f64 *s) {
    const double v[15] = {s->load, s->angle, s->rolling_radius, s->x_ref, s->y_ref_track,
                          s->z_ref_track, s->y_ref_rail, s->xi, s->eta, s->phi,
                          s->fx, s->fy, s->mz, s->pmax, s->area};
    for (int q = 0; q < 15; q++) printf(" %016" PRIx64, bits64(v[q]));
}

static void print_slot32(const wrc_slot_f32 *s) {
    const float v[15] = {s->load, s->angle, s->rolling_radius, s->x_ref, s->y_ref_track,
                         s->z_ref_track, s->y_ref_rail, s->xi, s->eta, s->phi,
                         s->fx, s->fy, s->mz, s->pmax, s->area};
    for (int q = 0; q < 15; q++) printf(" %08" PRIx32, bits32(v[q]));
}

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: %s TABLE_F64 TABLE_F32 TABLE_OVER_CAPACITY_F64\n", argv[0]);
        return 2;
    }
    size_t n64, n32, ncap;
    uint8_t *t64 = read_file(argv[1], &n64);
    uint8_t *t32 = read_file(argv[2], &n32);
    uint8_t *tcap = read_file(argv[3], &ncap);

    /* load and validate once */
    wrc_table_info info;
    expect("check_f64", wrc_table_check_f64(t64, n64, &info), WRC_OK);
    printf("info %u %u %u %u %u %u %zu\n", info.value_bytes, info.n_dy, info.n_load, info.slots,
           info.strips, info.side, info.total_bytes);
    size_t want = 0;
    expect("table_bytes_f64",
           wrc_table_bytes_f64(info.n_dy, info.n_load, info.slots, info.strips, &want), WRC_OK);
    if (want != n64) {
        fprintf(stderr, "wrc_table_bytes_f64 %zu, file %zu\n", want, n64);
        failures++;
    }
    wrc_table_info info32;
    expect("check_f32", wrc_table_check_f32(t32, n32, &info32), WRC_OK);

    /* the lateral-shift sweep */
    for (int i = 0; i <= 24; i++) {
        double dy = -8.0 + 0.5 * i;
        wrc_step_input_f64 in = input_f64(dy);
        wrc_step_output_f64 out;
        wrc_status s = wrc_step_f64(t64, n64, &in, &out);
        printf("f64 %d %d %016" PRIx64 " %016" PRIx64 " %u", i, (int)s,
               bits64(out.vertical_approach), bits64(out.vertical_load), out.n_slots);
        for (uint32_t k = 0; k < out.n_slots && k < WRC_MAX_SLOTS; k++) print_slot64(&out.slots[k]);
        printf("\n");
        wrc_step_input_f32 in32 = input_f32(dy);
        wrc_step_output_f32 out32;
        s = wrc_step_f32(t32, n32, &in32, &out32);
        printf("f32 %d %d %08" PRIx32 " %08" PRIx32 " %u", i, (int)s,
               bits32(out32.vertical_approach), bits32(out32.vertical_load), out32.n_slots);
        for (uint32_t k = 0; k < out32.n_slots && k < WRC_MAX_SLOTS; k++)
            print_slot32(&out32.slots[k]);
        printf("\n");
        /* the time loop's step from the cold step's output, in place (previous == output) */
        wrc_step_output_f64 loop = out;
        s = wrc_step_f64(t64, n64, &in, &loop);
        if (s == WRC_OK) s = wrc_step_from_f64(t64, n64, &in, &loop, &loop);
        printf("g64 %d %d %016" PRIx64 " %016" PRIx64 " %u", i, (int)s,
               bits64(loop.vertical_approach), bits64(loop.vertical_load), loop.n_slots);
        for (uint32_t k = 0; k < loop.n_slots && k < WRC_MAX_SLOTS; k++)
            print_slot64(&loop.slots[k]);
        printf("\n");
        wrc_step_output_f32 loop32 = out32;
        s = wrc_step_from_f32(t32, n32, &in32, &out32, &loop32);
        printf("g32 %d %d %08" PRIx32 " %08" PRIx32 " %u", i, (int)s,
               bits32(loop32.vertical_approach), bits32(loop32.vertical_load), loop32.n_slots);
        for (uint32_t k = 0; k < loop32.n_slots && k < WRC_MAX_SLOTS; k++)
            print_slot32(&loop32.slots[k]);
        printf("\n");
    }

    /* bad inputs */
    wrc_step_output_f64 out;
    wrc_step_input_f64 in = input_f64(0.0);
    in.fz = NAN;
    expect("nan_load", wrc_step_f64(t64, n64, &in, &out), WRC_ERR_NON_FINITE);
    if (out.n_slots != 0 || out.vertical_load != 0.0) {
        fprintf(stderr, "output not zeroed on failure\n");
        failures++;
    }
    in = input_f64(NAN);
    expect("nan_shift", wrc_step_f64(t64, n64, &in, &out), WRC_ERR_NON_FINITE);
    in = input_f64(0.0);
    in.fz = -83300.0;
    expect("negative_load", wrc_step_f64(t64, n64, &in, &out), WRC_ERR_NON_POSITIVE);
    in = input_f64(0.0);
    in.mu = 0.0;
    expect("zero_mu", wrc_step_f64(t64, n64, &in, &out), WRC_ERR_NON_POSITIVE);
    in = input_f64(30.0);
    expect("shift_outside_table", wrc_step_f64(t64, n64, &in, &out), WRC_ERR_OUT_OF_RANGE);
    in = input_f64(0.0);
    in.fz = 1e7;
    expect("load_outside_table", wrc_step_f64(t64, n64, &in, &out), WRC_ERR_OUT_OF_RANGE);
    in = input_f64(0.0);
    in.normalisation = 7;
    expect("bad_normalisation", wrc_step_f64(t64, n64, &in, &out), WRC_ERR_BAD_ARGUMENT);

    uint8_t *bad = malloc(n64);
    if (!bad) return 2;
    memcpy(bad, t64, n64);
    bad[4000] ^= 0x10; /* one flipped payload bit */
    expect("flipped_payload_byte", wrc_table_check_f64(bad, n64, &info), WRC_ERR_TABLE_CHECKSUM);
    if (info.total_bytes != 0) {
        fprintf(stderr, "info not zeroed on failure\n");
        failures++;
    }
    memcpy(bad, t64, n64);
    bad[0] ^= 0x01; /* flipped magic */
    in = input_f64(0.0);
    expect("flipped_magic_step", wrc_step_f64(bad, n64, &in, &out), WRC_ERR_TABLE_MAGIC);
    memcpy(bad, t64, n64);
    bad[8] = 6; /* version 6 (unknown) */
    expect("wrong_version", wrc_table_check_f64(bad, n64, NULL), WRC_ERR_TABLE_VERSION);
    bad[8] = 1; /* version 1 (evenly spaced shifts): rebuild */
    expect("version_1", wrc_table_check_f64(bad, n64, NULL), WRC_ERR_TABLE_VERSION);
    bad[8] = 2; /* version 2 (all slots stored, no roll mapping): rebuild */
    expect("version_2", wrc_table_check_f64(bad, n64, NULL), WRC_ERR_TABLE_VERSION);
    bad[8] = 3; /* version 3 (no yaw coefficients): rebuild */
    expect("version_3", wrc_table_check_f64(bad, n64, NULL), WRC_ERR_TABLE_VERSION);
    bad[8] = 4; /* version 4 (one roll mapping for shape and frame): rebuild */
    expect("version_4", wrc_table_check_f64(bad, n64, NULL), WRC_ERR_TABLE_VERSION);
    free(bad);
    expect("truncated_table", wrc_table_check_f64(t64, n64 - 1, NULL), WRC_ERR_TABLE_LENGTH);
    expect("truncated_table_step", wrc_step_f64(t64, n64 - 1, &in, &out), WRC_ERR_TABLE_LENGTH);
    expect("shorter_than_header", wrc_table_check_f64(t64, 100, NULL), WRC_ERR_TABLE_LENGTH);
    /* an undersized buffer: the caller's buffer holds 8 bytes less than the header's size */
    expect("undersized_buffer", wrc_table_check_f64(t64, want - 8, NULL), WRC_ERR_TABLE_LENGTH);
    expect("size_overflow",
           wrc_table_bytes_f64(UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX, &want),
           WRC_ERR_BAD_ARGUMENT);
    expect("f32_table_to_f64", wrc_table_check_f64(t32, n32, NULL), WRC_ERR_TABLE_PRECISION);
    expect("f64_table_to_f32", wrc_table_check_f32(t64, n64, NULL), WRC_ERR_TABLE_PRECISION);
    expect("over_capacity", wrc_table_check_f64(tcap, ncap, NULL), WRC_ERR_CAPACITY);
    expect("over_capacity_step", wrc_step_f64(tcap, ncap, &in, &out), WRC_ERR_CAPACITY);
    expect("null_table", wrc_table_check_f64(NULL, n64, &info), WRC_ERR_NULL_POINTER);
    expect("null_table_step", wrc_step_f64(NULL, n64, &in, &out), WRC_ERR_NULL_POINTER);
    expect("null_input", wrc_step_f64(t64, n64, NULL, &out), WRC_ERR_NULL_POINTER);
    expect("null_output", wrc_step_f64(t64, n64, &in, NULL), WRC_ERR_NULL_POINTER);
    expect("null_size", wrc_table_bytes_f64(2, 2, 1, 2, NULL), WRC_ERR_NULL_POINTER);
    in = input_f64(0.0);
    wrc_step_output_f64 prev;
    expect("cold_step", wrc_step_f64(t64, n64, &in, &prev), WRC_OK);
    expect("null_previous", wrc_step_from_f64(t64, n64, &in, NULL, &out), WRC_ERR_NULL_POINTER);
    prev.slots[0].load = NAN;
    expect("nan_previous", wrc_step_from_f64(t64, n64, &in, &prev, &out), WRC_ERR_NON_FINITE);
    prev.slots[0].load = 0.0;
    prev.n_slots = WRC_MAX_SLOTS + 1;
    expect("previous_other_table", wrc_step_from_f64(t64, n64, &in, &prev, &out),
           WRC_ERR_BAD_ARGUMENT);
    wrc_step_input_f32 in32 = input_f32(0.0);
    wrc_step_output_f32 out32;
    in32.fz = -1.0f;
    expect("negative_load_f32", wrc_step_f32(t32, n32, &in32, &out32), WRC_ERR_NON_POSITIVE);
    if (strcmp(wrc_status_name(WRC_ERR_CAPACITY), "WRC_ERR_CAPACITY") != 0 ||
        strcmp(wrc_status_name(99), "unknown status") != 0) {
        fprintf(stderr, "wrc_status_name\n");
        failures++;
    }

    free(t64);
    free(t32);
    free(tcap);
    if (failures) {
        fprintf(stderr, "%d failures\n", failures);
        return 1;
    }
    printf("ok\n");
    return 0;
}
