/* C ABI: the shared block frame of every block kind (Execute-type with Done or
 * InVelocity, MC_Stop holding, immediate, Enable-type), bad enumerations refused with
 * their ErrorID, CircMode RADIUS and the transition modes through the header's defines. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "motion_lib.h"

#define FAIL(code, ...) do { fprintf(stderr, __VA_ARGS__); fprintf(stderr, "\n"); return code; } while (0)

int main(void) {
    McEngine *eng = mc_engine_create(0.001, 8);
    MC_AxisConfig_C cfg;
    memset(&cfg, 0, sizeof cfg);
    cfg.VelocityLimit = 1000.0;
    cfg.AccelerationLimit = 5000.0;
    cfg.DecelerationLimit = 5000.0;
    cfg.JerkLimit = 50000.0;
    McIndex ax = 0;
    if (mc_engine_add_axis(eng, &cfg, &ax) != MC_OK) FAIL(1, "add axis");
    MC_Power_C power;
    memset(&power, 0, sizeof power);
    power.Enable = true;
    mc_power(eng, ax, &power);
    if (!power.Status) FAIL(1, "not powered");

    /* MC_SetOverride: AccFactor in (0, 1]; 2 is refused. */
    MC_SetOverride_C ov;
    memset(&ov, 0, sizeof ov);
    ov.Enable = true;
    ov.VelFactor = 1.0;
    ov.AccFactor = 2.0;
    mc_set_override(eng, ax, &ov);
    if (!ov.Error || ov.ErrorID != MC_ERR_INVALID_OVERRIDE) FAIL(2, "AccFactor 2 accepted");
    ov.AccFactor = 0.5;
    mc_set_override(eng, ax, &ov);
    if (!ov.Enabled || ov.Error) FAIL(3, "override refused %u", (unsigned)ov.ErrorID);

    /* MC_MoveVelocity: a bad Direction is refused, a good one reaches InVelocity. */
    MC_MoveVelocity_C mv;
    memset(&mv, 0, sizeof mv);
    mv.Execute = true;
    mv.Velocity = 100.0;
    mv.Acceleration = 1000.0;
    mv.Deceleration = 1000.0;
    mv.Direction = 9;
    mc_move_velocity(eng, ax, &mv);
    if (!mv.Error || mv.ErrorID != MC_ERR_INVALID_DIRECTION || mv.Busy) FAIL(4, "bad direction");
    mv.Execute = false;
    mc_move_velocity(eng, ax, &mv);
    if (mv.Error) FAIL(5, "error not reset");
    mv.Execute = true;
    mv.Direction = MC_POSITIVE_DIRECTION;
    int cycles = 0;
    for (; cycles < 5000 && !mv.InVelocity; cycles++) {
        mc_move_velocity(eng, ax, &mv);
        if (!mv.Busy || !mv.Active) FAIL(6, "not busy/active");
        mc_engine_step(eng);
    }
    if (!mv.InVelocity || mc_axis_state(eng, ax) != 4) FAIL(7, "no InVelocity");

    /* MC_Stop: Done while Execute is TRUE keeps the axis Stopping; the move is aborted. */
    MC_Stop_C stop;
    memset(&stop, 0, sizeof stop);
    stop.Execute = true;
    stop.Deceleration = 2000.0;
    for (cycles = 0; cycles < 5000 && !stop.Done; cycles++) {
        mc_stop(eng, ax, &stop);
        mc_engine_step(eng);
    }
    mc_move_velocity(eng, ax, &mv);
    if (!mv.CommandAborted || mv.Busy || mv.InVelocity) FAIL(8, "move not aborted");
    mc_stop(eng, ax, &stop);
    if (!stop.Done || mc_axis_state(eng, ax) != 6) FAIL(9, "stop does not hold");
    stop.Execute = false;
    mc_stop(eng, ax, &stop);
    if (stop.Done || mc_axis_state(eng, ax) != 1) FAIL(10, "stop not released");

    /* MC_Reset outside ErrorStop: Done, reset on the falling edge. */
    MC_Reset_C rst;
    memset(&rst, 0, sizeof rst);
    rst.Execute = true;
    mc_reset(eng, ax, &rst);
    if (!rst.Done) FAIL(11, "reset not done");
    rst.Execute = false;
    mc_reset(eng, ax, &rst);
    if (rst.Done) FAIL(12, "reset Done held");

    /* Group X/Y: half circle of radius 10 in CircMode RADIUS, centre (10, 0). */
    McIndex ay = 0;
    if (mc_engine_add_axis(eng, &cfg, &ay) != MC_OK) FAIL(1, "add axis");
    MC_Power_C power2;
    memset(&power2, 0, sizeof power2);
    power2.Enable = true;
    mc_power(eng, ay, &power2);
    McIndex g = 0;
    if (mc_engine_add_group(eng, &g) != MC_OK) FAIL(1, "add group");
    MC_AddAxisToGroup_C add;
    for (uint32_t i = 0; i < 2; i++) {
        memset(&add, 0, sizeof add);
        add.Execute = true;
        add.Axis = i == 0 ? ax : ay;
        add.IdentInGroup = i;
        mc_add_axis_to_group(eng, g, &add);
        if (!add.Done) FAIL(13, "add %u", (unsigned)add.ErrorID);
    }
    double x0 = mc_axis_set_position(eng, ax);
    MC_GroupEnable_C en;
    memset(&en, 0, sizeof en);
    en.Execute = true;
    mc_group_enable(eng, g, &en);
    if (!en.Done) FAIL(14, "enable %u", (unsigned)en.ErrorID);
    MC_MoveCircularAbsolute_C circ;
    memset(&circ, 0, sizeof circ);
    circ.Execute = true;
    circ.CircMode = MC_CIRC_RADIUS;
    circ.AuxPoint[2] = 10.0;
    circ.EndPoint[0] = x0 + 20.0;
    circ.EndPoint[1] = 0.0;
    circ.PathChoice = MC_COUNTER_CLOCKWISE;
    circ.Velocity = 50.0;
    circ.Acceleration = 1000.0;
    circ.Deceleration = 1000.0;
    circ.TransitionMode = MC_TM_NONE;
    double worst = 0.0;
    for (cycles = 0; cycles < 20000 && !circ.Done; cycles++) {
        mc_move_circular_absolute(eng, g, &circ);
        if (circ.Error) FAIL(15, "circle error %u", (unsigned)circ.ErrorID);
        mc_engine_step(eng);
        double dx = mc_axis_set_position(eng, ax) - (x0 + 10.0);
        double dy = mc_axis_set_position(eng, ay);
        double dev = fabs(sqrt(dx * dx + dy * dy) - 10.0);
        if (dev > worst) worst = dev;
    }
    if (!circ.Done || worst > 1e-9) FAIL(16, "circle: done %d, radius deviation %g", circ.Done, worst);
    if (fabs(mc_axis_set_position(eng, ax) - (x0 + 20.0)) > 1e-9) FAIL(17, "circle end");

    /* TMStartVelocity is refused; TMMaxCornerDeviation is accepted. */
    MC_MoveLinearAbsolute_C line;
    memset(&line, 0, sizeof line);
    line.Execute = true;
    line.Position[0] = x0;
    line.Velocity = 50.0;
    line.Acceleration = 500.0;
    line.Deceleration = 500.0;
    line.BufferMode = MC_BLENDING_LOW;
    line.TransitionMode = 1;
    line.TransitionParameter = 1.0;
    mc_move_linear_absolute(eng, g, &line);
    if (!line.Error || line.ErrorID != MC_ERR_INVALID_TRANSITION_MODE) FAIL(18, "TM 1 accepted");
    line.Execute = false;
    mc_move_linear_absolute(eng, g, &line);
    line.Execute = true;
    line.TransitionMode = MC_TM_MAX_CORNER_DEVIATION;
    mc_move_linear_absolute(eng, g, &line);
    if (line.Error || !line.Busy) FAIL(19, "TM 4 refused %u", (unsigned)line.ErrorID);

    /* MC_GroupStop holds GroupStopping while Execute is TRUE. */
    MC_GroupStop_C gs;
    memset(&gs, 0, sizeof gs);
    gs.Execute = true;
    gs.Deceleration = 1000.0;
    for (cycles = 0; cycles < 5000 && !gs.Done; cycles++) {
        mc_group_stop(eng, g, &gs);
        mc_engine_step(eng);
    }
    mc_group_stop(eng, g, &gs);
    if (!gs.Done || mc_group_state(eng, g) != 4) FAIL(20, "group stop does not hold");
    gs.Execute = false;
    mc_group_stop(eng, g, &gs);
    if (mc_group_state(eng, g) != 1) FAIL(21, "group stop not released");

    /* MC_CamIn: a law too fast for the slave (master up to 1000 mm/s, slope about 1, slave
       limited to 100 mm/s) is refused with ErrorID 33; under a slow master it couples. */
    {
        MC_AxisConfig_C sc = cfg;
        sc.VelocityLimit = 100.0;
        McIndex slave = 0, fast = 0, slow = 0, table = 0;
        if (mc_engine_add_axis(eng, &sc, &slave) != MC_OK) FAIL(22, "add slave");
        if (mc_engine_add_axis(eng, &cfg, &fast) != MC_OK) FAIL(22, "add master");
        MC_AxisConfig_C lc = cfg;
        lc.VelocityLimit = 10.0;
        lc.AccelerationLimit = 10.0;
        lc.DecelerationLimit = 10.0;
        lc.JerkLimit = 100.0;
        if (mc_engine_add_axis(eng, &lc, &slow) != MC_OK) FAIL(22, "add slow master");
        McIndex each[3] = {slave, fast, slow};
        for (int k = 0; k < 3; k++) {
            MC_Power_C p;
            memset(&p, 0, sizeof p);
            p.Enable = true;
            mc_power(eng, each[k], &p);
        }
        const double m[3] = {0.0, 10.0, 20.0}, s[3] = {0.0, 10.0, 0.0};
        if (mc_engine_add_cam_table(eng, m, s, 3, &table) != MC_OK) FAIL(23, "add cam table");
        MC_CamIn_C cam;
        memset(&cam, 0, sizeof cam);
        cam.Execute = true;
        cam.CamTableID = table;
        cam.Periodic = true;
        mc_cam_in(eng, fast, slave, &cam);
        if (!cam.Error || cam.ErrorID != MC_ERR_CAM_BEYOND_SLAVE_LIMITS)
            FAIL(24, "a cam too fast for the slave accepted (%u)", (unsigned)cam.ErrorID);
        MC_CamIn_C ok;
        memset(&ok, 0, sizeof ok);
        ok.Execute = true;
        ok.CamTableID = table;
        ok.Periodic = true;
        for (cycles = 0; cycles < 5000 && !ok.InSync; cycles++) {
            mc_cam_in(eng, slow, slave, &ok);
            if (ok.Error) FAIL(25, "cam refused %u", (unsigned)ok.ErrorID);
            mc_engine_step(eng);
        }
        if (!ok.InSync || mc_axis_state(eng, slave) != 5) FAIL(26, "not in sync");
    }

    printf("frames ok\n");
    mc_engine_destroy(eng);
    return 0;
}
