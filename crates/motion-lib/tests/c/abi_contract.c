/* C ABI contract: version, struct sizes, status codes for NULL and invalid handles and arguments, bad
 * indices, and the panic guard (a panic returns MC_STATUS_PANIC and poisons the engine, never aborts). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "motion_lib.h"

#define FAIL(code, ...) do { fprintf(stderr, __VA_ARGS__); fprintf(stderr, "\n"); return code; } while (0)
#define SIZE(T) do { if (mc_sizeof(#T) != sizeof(T)) FAIL(2, "sizeof " #T ": C %zu, library %zu", sizeof(T), mc_sizeof(#T)); checked++; } while (0)

/* Zeroed memory that is not an engine (large enough for any McEngine, suitably aligned). */
static double not_an_engine[1 << 16];

int main(void) {
    int checked = 0;
    if (mc_abi_version() != MC_ABI_VERSION) FAIL(1, "ABI version %u, header %u", mc_abi_version(), (unsigned)MC_ABI_VERSION);
    /* STRUCT SIZES BEGIN */
    SIZE(MC_AxisConfig_C); SIZE(MC_Power_C); SIZE(MC_Home_C); SIZE(MC_Stop_C); SIZE(MC_Halt_C);
    SIZE(MC_MoveAbsolute_C); SIZE(MC_MoveRelative_C); SIZE(MC_MoveAdditive_C); SIZE(MC_MoveVelocity_C);
    SIZE(MC_Reset_C); SIZE(MC_ReadActualPosition_C); SIZE(MC_ReadActualVelocity_C); SIZE(MC_ReadStatus_C);
    SIZE(MC_ReadAxisError_C); SIZE(MC_SetPosition_C); SIZE(MC_SetOverride_C); SIZE(MC_GearIn_C);
    SIZE(MC_GearOut_C); SIZE(MC_CamOut_C); SIZE(MC_CamTableSelect_C); SIZE(MC_CamIn_C);
    SIZE(MC_AddAxisToGroup_C); SIZE(MC_RemoveAxisFromGroup_C); SIZE(MC_UngroupAllAxes_C);
    SIZE(MC_GroupEnable_C); SIZE(MC_GroupDisable_C); SIZE(MC_GroupReset_C); SIZE(MC_GroupStop_C);
    SIZE(MC_GroupHome_C); SIZE(MC_GroupHalt_C); SIZE(MC_MoveLinearAbsolute_C); SIZE(MC_MoveLinearRelative_C);
    SIZE(MC_MoveDirectAbsolute_C); SIZE(MC_MoveCircularAbsolute_C); SIZE(MC_MoveCircularRelative_C);
    SIZE(MC_GroupReadActualPosition_C); SIZE(MC_GroupReadActualVelocity_C); SIZE(MC_GroupReadStatus_C);
    /* STRUCT SIZES END */
    if (mc_sizeof("no such struct") != 0 || mc_sizeof(NULL) != 0) FAIL(3, "unknown names have size 0");

    /* NULL handle: every kind of call says so. */
    MC_Power_C power;
    memset(&power, 0, sizeof power);
    power.Enable = true;
    if (mc_engine_step(NULL) != MC_STATUS_NULL_HANDLE) FAIL(4, "step(NULL)");
    if (mc_power(NULL, 0, &power) != MC_STATUS_NULL_HANDLE) FAIL(5, "power(NULL)");
    if (mc_axis_state(NULL, 0) != MC_STATUS_NULL_HANDLE) FAIL(6, "axis_state(NULL)");
    if (!isnan(mc_axis_set_position(NULL, 0))) FAIL(7, "set_position(NULL) is not NaN");
    if (mc_engine_destroy(NULL) != MC_STATUS_NULL_HANDLE) FAIL(8, "destroy(NULL)");
    McIndex index = 0;
    MC_AxisConfig_C cfg;
    memset(&cfg, 0, sizeof cfg);
    if (mc_engine_add_axis(NULL, &cfg, &index) != MC_STATUS_NULL_HANDLE) FAIL(9, "add_axis(NULL)");

    /* A pointer that is not an engine. */
    McEngine *bogus = (McEngine *)(void *)not_an_engine;
    if (mc_engine_step(bogus) != MC_STATUS_BAD_HANDLE) FAIL(10, "step(bogus)");
    if (mc_power(bogus, 0, &power) != MC_STATUS_BAD_HANDLE) FAIL(11, "power(bogus)");
    if (mc_group_state(bogus, 0) != MC_STATUS_BAD_HANDLE) FAIL(12, "group_state(bogus)");
    if (mc_engine_destroy(bogus) != MC_STATUS_BAD_HANDLE) FAIL(13, "destroy(bogus)");

    /* A live engine: NULL arguments, a bad configuration, bad indices. */
    McEngine *eng = mc_engine_create(0.001, 8);
    if (eng == NULL) FAIL(14, "create");
    if (mc_engine_create(-1.0, 8) != NULL) FAIL(15, "a negative cycle time is refused");
    if (mc_engine_add_axis(eng, &cfg, &index) != MC_STATUS_BAD_CONFIG) FAIL(16, "zero limits are refused");
    cfg.VelocityLimit = 100.0;
    cfg.AccelerationLimit = 1000.0;
    cfg.DecelerationLimit = 1000.0;
    cfg.JerkLimit = 10000.0;
    if (mc_engine_add_axis(eng, NULL, &index) != MC_STATUS_NULL_ARGUMENT) FAIL(17, "add_axis(config NULL)");
    if (mc_engine_add_axis(eng, &cfg, NULL) != MC_STATUS_NULL_ARGUMENT) FAIL(18, "add_axis(index NULL)");
    if (mc_engine_add_axis(eng, &cfg, &index) != MC_OK || index != 0) FAIL(19, "add_axis");
    if (mc_power(eng, 0, NULL) != MC_STATUS_NULL_ARGUMENT) FAIL(20, "power(fb NULL)");
    if (mc_power(eng, 7, &power) != MC_STATUS_BAD_INDEX) FAIL(21, "power on axis 7");
    if (!power.Error || power.ErrorID == 0) FAIL(22, "the block shows the bad axis too");
    memset(&power, 0, sizeof power);
    power.Enable = true;
    if (mc_power(eng, 0, &power) != MC_OK) FAIL(23, "power");
    if (mc_axis_state(eng, 9) != MC_STATUS_BAD_INDEX) FAIL(24, "axis_state(9)");
    if (!isnan(mc_axis_set_velocity(eng, 9))) FAIL(25, "set_velocity(9) is not NaN");
    MC_GroupEnable_C ge;
    memset(&ge, 0, sizeof ge);
    ge.Execute = true;
    if (mc_group_enable(eng, 3, &ge) != MC_STATUS_BAD_INDEX) FAIL(26, "group_enable on group 3");
    if (mc_engine_step(eng) != MC_OK) FAIL(27, "step");

    /* The panic guard: the call returns, the engine is poisoned, destroy still frees it. */
    if (mc_engine_selftest_panic(eng) != MC_STATUS_PANIC) FAIL(28, "panic not reported");
    if (mc_engine_step(eng) != MC_STATUS_PANIC) FAIL(29, "a poisoned engine does not step");
    if (mc_power(eng, 0, &power) != MC_STATUS_PANIC) FAIL(30, "a poisoned engine takes no block call");
    if (mc_axis_state(eng, 0) != MC_STATUS_PANIC) FAIL(31, "a poisoned engine has no state");
    if (mc_engine_destroy(eng) != MC_OK) FAIL(32, "destroy");
    printf("abi ok, %d struct sizes\n", checked);
    return 0;
}
