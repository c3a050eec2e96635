// Validation and per-mille scaling of the servo axis configuration (see servo_axis_config.hpp).
#include "pac/sim/servo_axis_config.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace pac::sim {

namespace {

void Require(bool ok, const char* field, const char* rule) {
    if (!ok) throw std::invalid_argument(std::string("ServoAxisConfig: ") + field + " " + rule);
}

bool Positive(double v) { return std::isfinite(v) && v > 0.0; }
bool NotNegative(double v) { return std::isfinite(v) && v >= 0.0; }

}  // namespace

void ServoAxisConfig::Validate() const {
    Require(Positive(traverseSpeed), "traverseSpeed", "must be > 0 and finite");
    Require(Positive(referenceSpeed), "referenceSpeed", "must be > 0 and finite");
    Require(Positive(creepSpeed), "creepSpeed", "must be > 0 and finite");
    Require(Positive(acceleration), "acceleration", "must be > 0 and finite");
    Require(Positive(deceleration), "deceleration", "must be > 0 and finite");
    Require(rampType == RampType::kLinear || rampType == RampType::kSCurve, "rampType", "must be linear or S");
    Require(std::isfinite(minTraverseRange), "minTraverseRange", "must be finite");
    Require(std::isfinite(maxTraverseRange), "maxTraverseRange", "must be finite");
    Require(minTraverseRange <= maxTraverseRange, "minTraverseRange", "must be <= maxTraverseRange");
    Require(!negativeLimitSwitch || std::isfinite(*negativeLimitSwitch), "negativeLimitSwitch", "must be finite");
    Require(!positiveLimitSwitch || std::isfinite(*positiveLimitSwitch), "positiveLimitSwitch", "must be finite");
    Require(!negativeLimitSwitch || !positiveLimitSwitch || *negativeLimitSwitch < *positiveLimitSwitch,
            "negativeLimitSwitch", "must be below positiveLimitSwitch");
    Require(std::isfinite(referenceSwitch), "referenceSwitch", "must be finite");
    Require(referenceCamSide == Direction::kPositive || referenceCamSide == Direction::kNegative,
            "referenceCamSide", "must be positive or negative");
    Require(Positive(indexPitch), "indexPitch", "must be > 0 and finite");
    Require(std::isfinite(indexOffset), "indexOffset", "must be finite");
    Require(std::isfinite(startPosition), "startPosition", "must be finite");
    Require(homingMode == HomingMode::kSwitch || homingMode == HomingMode::kSwitchAndIndex ||
                homingMode == HomingMode::kLoadOnSwitch,
            "homingMode", "must be 0, 1 or 2");
    Require(homingDirection == Direction::kPositive || homingDirection == Direction::kNegative, "homingDirection",
            "must be positive or negative");
    Require(std::isfinite(referencePosition), "referencePosition", "must be finite");
    Require(NotNegative(toleranceWindow), "toleranceWindow", "must be >= 0 and finite");
    Require(toleranceDelay.count() >= 0, "toleranceDelay", "must be >= 0");
    Require(!std::isnan(followingErrorLimit) && followingErrorLimit > 0.0, "followingErrorLimit",
            "must be > 0 (infinity: no monitoring)");
    Require(enableMode == EnableMode::kHalt || enableMode == EnableMode::kIdle || enableMode == EnableMode::kSafe,
            "enableMode", "must be HALT, IDLE or SAFE");
    Require(NotNegative(maxDisplacementOff), "maxDisplacementOff", "must be >= 0 and finite");
}

std::optional<Dynamics> ScaledDynamics(const ServoAxisConfig& config, std::uint32_t speedPerMille,
                                       std::uint32_t accelerationPerMille) {
    if (speedPerMille < 1 || speedPerMille > 1000) return std::nullopt;
    if (accelerationPerMille < 1 || accelerationPerMille > 65535) return std::nullopt;
    const double speed = static_cast<double>(speedPerMille);
    const double accel = static_cast<double>(accelerationPerMille);
    return Dynamics{speed * config.traverseSpeed / 1000.0, accel * config.acceleration / 1000.0,
                    accel * config.deceleration / 1000.0};
}

}  // namespace pac::sim
