// Why a scenario was refused: the JSONPath of the offending value ($.steps[2].param; empty for the
// file as a whole) and the reason ("out of range: 70000 is not in 0..65535").
#pragma once

#include <stdexcept>
#include <string>

namespace pac::scenario {

class ScenarioError : public std::runtime_error {
public:
    ScenarioError(std::string path, std::string reason)
        : std::runtime_error(path.empty() ? reason : path + ": " + reason),
          path_(std::move(path)),
          reason_(std::move(reason)) {}

    const std::string& Path() const { return path_; }
    const std::string& Reason() const { return reason_; }

private:
    std::string path_;
    std::string reason_;
};

}  // namespace pac::scenario
