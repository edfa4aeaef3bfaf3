/* Minimal use of the wrc C interface (shown in docs/ffi.md; ffi/tests/c_api.rs compiles and runs it). */
#include "wrc.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv) {
    if (argc != 2) return 2;
    /* 1. Load a contact table (bytes from flash, a file, ...) and validate it once. */
    FILE *f = fopen(argv[1], "rb");
    if (!f) return 2;
    fseek(f, 0, SEEK_END);
    size_t len = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    uint8_t *table = malloc(len);
    if (!table || fread(table, 1, len, f) != len) return 2;
    fclose(f);
    wrc_table_info info;
    wrc_status s = wrc_table_check_f64(table, len, &info);
    if (s != WRC_OK) {
        fprintf(stderr, "table: %s\n", wrc_status_name(s));
        return 1;
    }
    /* 2. Every time step, per wheel: pose, load, kinematics, friction in; patches out. */
    wrc_step_input_f64 in = {
        .dy = -2.0,              /* mm, +left */
        .fz = 83300.0,           /* N */
        .speed = 27777.8,        /* mm/s */
        .pitch_rate = 27777.8 / 460.0, /* rad/s: nominal rolling, R0 460 mm */
        .mu = 0.3,
    };
    wrc_step_output_f64 out;
    s = wrc_step_f64(table, len, &in, &out);
    if (s != WRC_OK) {
        fprintf(stderr, "step: %s\n", wrc_status_name(s));
        return 1;
    }
    for (uint32_t k = 0; k < out.n_slots; k++) {
        const wrc_slot_f64 *p = &out.slots[k];
        if (p->load > 0.0)
            printf("patch %u: N %.0f N, angle %.4f rad, Fx %.0f N, Fy %.0f N, Mz %.0f N mm, "
                   "pmax %.0f MPa, area %.1f mm2\n",
                   k, p->load, p->angle, p->fx, p->fy, p->mz, p->pmax, p->area);
    }
    printf("vertical approach %.4f mm, vertical load %.0f N\n", out.vertical_approach,
           out.vertical_load);
    free(table);
    return 0;
}
