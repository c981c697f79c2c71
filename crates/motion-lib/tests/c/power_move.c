/* C ABI acceptance: MC_Power + MC_MoveAbsolute to Done, then a group line move. */
#include <stdio.h>
#include <string.h>
#include "motion_lib.h"

int main(void) {
    McEngine *eng = mc_engine_create(0.001, 8);
    if (eng == NULL) { fprintf(stderr, "create failed\n"); return 1; }
    MC_AxisConfig_C cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.VelocityLimit = 1000.0;
    cfg.AccelerationLimit = 5000.0;
    cfg.DecelerationLimit = 5000.0;
    cfg.JerkLimit = 50000.0;
    int32_t axis = mc_engine_add_axis(eng, &cfg);
    if (axis < 0) { fprintf(stderr, "add axis failed\n"); return 2; }

    MC_Power_C power;
    MC_MoveAbsolute_C move;
    memset(&power, 0, sizeof power);
    memset(&move, 0, sizeof move);
    power.Enable = true;
    move.Execute = true;
    move.Position = 250.0;
    move.Velocity = 500.0;
    move.Acceleration = 2000.0;
    move.Deceleration = 2000.0;
    move.Jerk = 20000.0;
    move.BufferMode = MC_ABORTING;
    move.Direction = MC_POSITIVE_DIRECTION;

    int done_cycle = -1;
    for (int cycle = 0; cycle < 10000; cycle++) {
        /* One PLC scan: call the blocks, then one interpolation cycle. */
        mc_power(eng, (uint32_t)axis, &power);
        mc_move_absolute(eng, (uint32_t)axis, &move);
        if (move.Error) { fprintf(stderr, "MoveAbsolute error %u\n", (unsigned)move.ErrorID); return 3; }
        if (move.Done) { done_cycle = cycle; break; }
        if (cycle > 0 && !move.Busy) { fprintf(stderr, "not busy\n"); return 4; }
        mc_engine_step(eng);
    }
    if (!power.Status || done_cycle < 0) { fprintf(stderr, "no Done\n"); return 5; }
    double p = mc_axis_set_position(eng, (uint32_t)axis);
    if (p < 249.999999 || p > 250.000001) { fprintf(stderr, "position %f\n", p); return 6; }
    if (mc_axis_state(eng, (uint32_t)axis) != 1) { fprintf(stderr, "not Standstill\n"); return 7; }

    /* A bad BufferMode is reported as an Error with its ErrorID. */
    MC_MoveAbsolute_C bad = move;
    memset(&bad._internal, 0, sizeof bad._internal);
    bad.Done = false;
    bad.BufferMode = 9;
    mc_move_absolute(eng, (uint32_t)axis, &bad);
    if (!bad.Error || bad.ErrorID != MC_ERR_INVALID_BUFFER_MODE) { fprintf(stderr, "bad mode accepted\n"); return 8; }

    printf("Done after %d cycles at %.6f\n", done_cycle, p);
    mc_engine_destroy(eng);
    return 0;
}
