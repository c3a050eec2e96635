// Validity of each command per operating mode (see command_table.hpp and docs/sim_cmd.md).
#include "pac/sim/command_table.hpp"

namespace pac::sim {

namespace {

constexpr ModeSet kHomeOnly{Mode::kHome};
constexpr ModeSet kAutoOnly{Mode::kAutomatic};
constexpr ModeSet kOnlineOnly{Mode::kOnline};
constexpr ModeSet kAll = ModeSet::All();

std::vector<CommandInfo> BuildTable() {
    return {
        // 5.1.1: the table marks 0600 for AUTOMATIC only, its description (5.2.1.1) for ONLINE too.
        {code::kStop, "cmd_stop", ModeSet{Mode::kAutomatic, Mode::kOnline}},
        // 5.1.1 marks home position only; 5.2.1.1 restarts a stopped AUTOMATIC with 0602, and the
        // simulator resumes a stopped ONLINE with 0603 alike (ModeMachine: 15 / 19, 35 / 39 only).
        {code::kStartAuto, "cmd_start_auto", ModeSet{Mode::kHome, Mode::kAutomatic}},
        {code::kStartOnline, "cmd_start_online", ModeSet{Mode::kHome, Mode::kOnline}},
        // 5.1.2, 5.1.3: parameters only in home position.
        {code::kSetSystemParameter, "cmd_set_system_parameter", kHomeOnly},
        {code::kGetSystemParameter, "cmd_get_system_parameter", kHomeOnly},
        {code::kGetSystemParameterMax, "cmd_get_system_parameter_max", kHomeOnly},
        {code::kGetSystemParameterMin, "cmd_get_system_parameter_min", kHomeOnly},
        {code::kSetAxisParameter, "cmd_set_axis_parameter", kHomeOnly},
        {code::kGetAxisParameter, "cmd_get_axis_parameter", kHomeOnly},
        {code::kGetAxisParameterMax, "cmd_get_axis_parameter_max", kHomeOnly},
        {code::kGetAxisParameterMin, "cmd_get_axis_parameter_min", kHomeOnly},
        // 5.1.4: element commands in every mode, except 0909 (5.2.4.15: home position only).
        {code::kGetSingleInput, "cmd_get_single_input", kAll},
        {code::kGetInputWord, "cmd_get_input_word", kAll},
        {code::kPutSingleOutput, "cmd_put_single_output", kAll},
        {code::kGetSingleOutput, "cmd_get_single_output", kAll},
        {code::kPutOutputWord, "cmd_put_output_word", kAll},
        {code::kGetOutputWord, "cmd_get_output_word", kAll},
        {code::kPutSingleFlag, "cmd_put_single_flag", kAll},
        {code::kGetSingleFlag, "cmd_get_single_flag", kAll},
        {code::kPutFlagWord, "cmd_put_flag_word", kAll},
        {code::kGetFlagWord, "cmd_get_flag_word", kAll},
        {code::kPutIntReg, "cmd_put_int_reg", kAll},
        {code::kGetIntReg, "cmd_get_int_reg", kAll},
        {code::kPutFloatReg, "cmd_put_float_reg", kAll},
        {code::kGetFloatReg, "cmd_get_float_reg", kAll},
        {code::kResetError, "cmd_reset_error", kHomeOnly},
        {code::kGetError, "cmd_get_error", kAll},
        {code::kGetState, "cmd_get_state", kAll},
        {code::kGetActualPos, "cmd_get_actual_pos", kAll},
        {code::kGetActualSpeed, "cmd_get_actual_speed", kAll},
        {code::kGetRotationControlPos, "cmd_get_rotation_control_pos", kAll},
        {code::kGetMaxTowfault, "cmd_get_max_towfault", kAll},
        {code::kGetStatusAxis, "cmd_get_status_axis", kAll},
        {code::kGetStatusAllAxis, "cmd_get_status_all_axis", kAll},
        {code::kGetTraverseAreaMin, "cmd_get_axis_traverse_area_min", kAll},
        {code::kGetTraverseAreaMax, "cmd_get_axis_traverse_area_max", kAll},
        {code::kGetAxisFollowingError, "cmd_get_axis_following_error", kAll},
        {code::kGetTemperature, "cmd_get_temperature", kAll},
        {code::kGetExtendedStatusAxis, "cmd_get_extended_status_axis", kAll},
        {code::kGetSystemFlag, "cmd_send_system_flag", kAll},
        {code::kGetSystemNReg, "cmd_send_system_n_reg", kAll},
        {code::kGetSystemRReg, "cmd_send_system_r_reg", kAll},
        // 5.1.5, 5.1.6.
        {code::kAbortAuto, "cmd_abort_auto", kAutoOnly},
        {code::kAbortOnline, "cmd_abort_online", kOnlineOnly},
        {code::kPutNoReference, "cmd_put_no_reference", kOnlineOnly},
        {code::kPutStartReference, "cmd_put_start_reference", kOnlineOnly},
        {code::kPutPositionNull, "cmd_put_position_null", kOnlineOnly},
        {code::kPutSetPosition, "cmd_put_set_position", kOnlineOnly},
        {code::kPosAxisAbsolute, "cmd_pos_axis_absolut", kOnlineOnly},
        {code::kPosAxisRelative, "cmd_pos_axis_relativ", kOnlineOnly},
        {code::kSetSpeedAxis, "cmd_set_speed_axis", kOnlineOnly},
        {code::kSetAccelerationAxis, "cmd_set_acceleration", kOnlineOnly},
        {code::kStartManualAbsolute, "cmd_start_manuell_axis_absolut", kOnlineOnly},
        {code::kStartManualRelative, "cmd_start_manuell_axis_relativ", kOnlineOnly},
        {code::kControlMoveAxis, "cmd_control_move_axis", kOnlineOnly},
        {code::kStopAxis, "cmd_abort_move_axis", kOnlineOnly},
        {code::kStartAxisAbsolute, "cmd_start_axis_absolut", kOnlineOnly},
        {code::kStartAxisRelative, "cmd_start_axis_relativ", kOnlineOnly},
        {code::kPutReferenceOnPosition, "cmd_put_axis_reference_on_position", kOnlineOnly},
        {code::kOnAxis, "cmd_on_axis", kOnlineOnly},
        {code::kOffAxis, "cmd_off_axis", kOnlineOnly},
        {code::kStopAxisMultiCmd, "cmd_stop_axis_multi_cmd", kOnlineOnly},
        // 5.1.6 marks every ONLINE command for ONLINE only; 5.2.6.20 asks for "automatic or online mode".
        {code::kSetMeasuringMode, "cmd_set_measuring_mode", ModeSet{Mode::kAutomatic, Mode::kOnline}},
        {code::kResetMeasuringMode, "cmd_reset_axis_measuring_mode", ModeSet{Mode::kAutomatic, Mode::kOnline}},
        {code::kPutLimitSwitchMonitoring, "cmd_put_limit_switch_monitoring_on_off", kOnlineOnly},
        {code::kPutConditionMoveAxis, "cmd_put_condition_move_axis", kOnlineOnly},
    };
}

}  // namespace

const std::vector<CommandInfo>& SupportedCommands() {
    static const std::vector<CommandInfo> table = BuildTable();
    return table;
}

const CommandInfo* FindCommand(std::uint16_t c) {
    for (const auto& info : SupportedCommands()) {
        if (info.code == c) return &info;
    }
    return nullptr;
}

}  // namespace pac::sim
