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
    McIndex axis = 0;
    if (mc_engine_add_axis(eng, &cfg, &axis) != MC_OK) { fprintf(stderr, "add axis failed\n"); return 2; }

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
        mc_power(eng, axis, &power);
        mc_move_absolute(eng, axis, &move);
        if (move.Error) { fprintf(stderr, "MoveAbsolute error %u\n", (unsigned)move.ErrorID); return 3; }
        if (move.Done) { done_cycle = cycle; break; }
        if (cycle > 0 && !move.Busy) { fprintf(stderr, "not busy\n"); return 4; }
        mc_engine_step(eng);
    }
    if (!power.Status || done_cycle < 0) { fprintf(stderr, "no Done\n"); return 5; }
    double p = mc_axis_set_position(eng, axis);
    if (p < 249.999999 || p > 250.000001) { fprintf(stderr, "position %f\n", p); return 6; }
    if (mc_axis_state(eng, axis) != 1) { fprintf(stderr, "not Standstill\n"); return 7; }

    /* A bad BufferMode is reported as an Error with its ErrorID. */
    MC_MoveAbsolute_C bad = move;
    memset(&bad._internal, 0, sizeof bad._internal);
    bad.Done = false;
    bad.BufferMode = 9;
    mc_move_absolute(eng, axis, &bad);
    if (!bad.Error || bad.ErrorID != MC_ERR_INVALID_BUFFER_MODE) { fprintf(stderr, "bad mode accepted\n"); return 8; }

    /* Error resets on the falling edge of Execute. */
    bad.Execute = false;
    mc_move_absolute(eng, axis, &bad);
    if (bad.Error || bad.ErrorID != 0) { fprintf(stderr, "error not reset\n"); return 9; }

    /* A second axis, a group of two, one MC_MoveLinearAbsolute to Done. */
    McIndex axis2 = 0, group = 0;
    if (mc_engine_add_axis(eng, &cfg, &axis2) != MC_OK || mc_engine_add_group(eng, &group) != MC_OK) {
        fprintf(stderr, "add axis/group failed\n");
        return 15;
    }
    MC_Power_C power2;
    memset(&power2, 0, sizeof power2);
    power2.Enable = true;
    mc_power(eng, axis2, &power2);
    MC_AddAxisToGroup_C add[2];
    memset(add, 0, sizeof add);
    for (uint32_t i = 0; i < 2; i++) {
        add[i].Execute = true;
        add[i].Axis = i == 0 ? axis : axis2;
        add[i].IdentInGroup = i;
        mc_add_axis_to_group(eng, group, &add[i]);
        if (!add[i].Done) { fprintf(stderr, "add axis %u: %u\n", (unsigned)i, (unsigned)add[i].ErrorID); return 10; }
    }
    MC_GroupEnable_C enable;
    memset(&enable, 0, sizeof enable);
    enable.Execute = true;
    mc_group_enable(eng, group, &enable);
    if (!enable.Done) { fprintf(stderr, "group enable %u\n", (unsigned)enable.ErrorID); return 11; }
    MC_MoveLinearAbsolute_C line;
    memset(&line, 0, sizeof line);
    line.Execute = true;
    line.Position[0] = 300.0;
    line.Position[1] = 40.0;
    line.Velocity = 200.0;
    line.Acceleration = 2000.0;
    line.Deceleration = 2000.0;
    line.BufferMode = MC_ABORTING;
    line.TransitionMode = MC_TM_NONE;
    int line_done = 0;
    for (int cycle = 0; cycle < 10000 && !line_done; cycle++) {
        mc_move_linear_absolute(eng, group, &line);
        if (line.Error) { fprintf(stderr, "line error %u\n", (unsigned)line.ErrorID); return 12; }
        line_done = line.Done;
        mc_engine_step(eng);
    }
    if (!line_done || mc_axis_set_position(eng, axis2) != 40.0) { fprintf(stderr, "line not done\n"); return 13; }
    if (mc_group_state(eng, group) != 1) { fprintf(stderr, "group not standby\n"); return 14; }

    printf("Done after %d cycles at %.6f\n", done_cycle, p);
    mc_engine_destroy(eng);
    return 0;
}
