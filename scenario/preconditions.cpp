#include "preconditions.hpp"

#include <map>
#include <optional>

#include "pac/sim/parameter_table.hpp"

namespace pac::scenario {

namespace {

constexpr std::uint16_t kStartOnline = 0x0603;        // PAC_CMD_START_ONLINE
constexpr std::uint16_t kSetSystemParameter = 0x0700;  // PAC_CMD_SET_SYSTEM_PARAMETER

bool ExpectsError(const Expectation& expect) { return expect.error.value_or(false) || expect.errorId.value_or(0) != 0; }

// What the controller will hold of system parameter 4 and the inputs, step by step.
class StopInputModel {
public:
    explicit StopInputModel(const ControllerSetup& setup)
        : parameters_(pac::sim::ParameterType::kInt32, pac::sim::DefaultSystemParameters()), inputs_(setup.inputs) {
        for (const auto& [number, value] : setup.systemParameters) {
            parameters_.Set(static_cast<std::uint16_t>(number), static_cast<std::uint32_t>(value));
        }
    }

    void Apply(const Step& step) {
        if (const auto* fault = std::get_if<FaultStep>(&step.action); fault && fault->kind == FaultKind::kSetInput) {
            inputs_[fault->number] = fault->value;
        }
        const auto* command = std::get_if<CommandStep>(&step.action);
        if (command && command->code == kSetSystemParameter && !ExpectsError(command->expect)) {
            parameters_.Set(command->param, command->data.bits);
        }
    }

    // Why START ONLINE will be refused, or nothing.
    std::optional<std::string> UnmetReason() const {
        const int input = parameters_.IntValue(pac::sim::sysparam::kStopInput).value_or(0);
        if (input == 0) {
            return std::string("START ONLINE without an external stop input: system parameter 4 is 0, so the "
                               "PA-CONTROL will not start ONLINE (manual 5.2.1.3; 0603 ends with error 44, a CTRL "
                               "request is ignored); give it one, e.g. \"controller\": {\"system_parameters\": "
                               "{\"4\": 1}, \"inputs\": {\"1\": true}}");
        }
        const auto it = inputs_.find(input);
        if (it == inputs_.end() || !it->second) {
            return "START ONLINE while the external stop input " + std::to_string(input) +
                   " (system parameter 4) has no power, so the PA-CONTROL will not start ONLINE (manual 5.2.1.3; "
                   "0603 ends with error 44, a CTRL request is ignored); power it: \"inputs\": {\"" +
                   std::to_string(input) + "\": true} or a set_input step";
        }
        return std::nullopt;
    }

private:
    pac::sim::ParameterTable parameters_;
    std::map<int, bool> inputs_;
};

// The step starts ONLINE and expects it to work (or says nothing about its end).
bool StartsOnline(const Step& step) {
    if (const auto* ctrl = std::get_if<CtrlStep>(&step.action)) {
        return ctrl->request == "PAC_REQ_START_ONLINE" && !ExpectsError(ctrl->expect);
    }
    const auto* command = std::get_if<CommandStep>(&step.action);
    return command && command->code == kStartOnline && !ExpectsError(command->expect);
}

}  // namespace

std::vector<PreconditionWarning> FindUnmetPreconditions(const Scenario& scenario) {
    std::vector<PreconditionWarning> warnings;
    StopInputModel model(scenario.controller);
    for (std::size_t i = 0; i < scenario.steps.size(); ++i) {
        if (StartsOnline(scenario.steps[i])) {
            if (auto reason = model.UnmetReason()) warnings.push_back({i, std::move(*reason)});
        }
        model.Apply(scenario.steps[i]);
    }
    return warnings;
}

}  // namespace pac::scenario
