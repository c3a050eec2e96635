// A recording of named signals (see trace.hpp).
#include "pac/trace.hpp"

#include <algorithm>
#include <stdexcept>

namespace pac {

std::string SignalInfo::Scope() const {
    const auto dot = path.rfind('.');
    return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::string SignalInfo::Name() const {
    const auto dot = path.rfind('.');
    return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::size_t Trace::AddSignal(SignalInfo info) {
    if (!times_.empty()) throw std::invalid_argument("Trace: signal " + info.path + " added after the first sample");
    if (info.path.empty() || info.Name().empty()) throw std::invalid_argument("Trace: a signal needs a name");
    if (info.path.find_first_of(" \t\n") != std::string::npos) {
        throw std::invalid_argument("Trace: \"" + info.path + "\" has a blank, which VCD cannot name");
    }
    if (info.kind == SignalKind::kReal) info.width = 64;
    if (info.width < 1 || info.width > 64) throw std::invalid_argument("Trace: " + info.path + " is not 1..64 bits wide");
    for (const auto& signal : signals_) {
        if (signal.path == info.path) throw std::invalid_argument("Trace: " + info.path + " added twice");
    }
    signals_.push_back(std::move(info));
    changes_.emplace_back();
    return signals_.size() - 1;
}

void Trace::Append(std::chrono::nanoseconds time, const std::vector<TraceValue>& values) {
    if (values.size() != signals_.size()) throw std::invalid_argument("Trace: one value per signal");
    if (!times_.empty() && time <= times_.back()) throw std::invalid_argument("Trace: sample times must increase");
    const std::size_t sample = times_.size();
    times_.push_back(time);
    for (std::size_t i = 0; i < values.size(); ++i) {
        TraceValue value = values[i];
        const int width = signals_[i].width;
        if (signals_[i].kind == SignalKind::kBits && width < 64) value.bits &= (std::uint64_t{1} << width) - 1;
        auto& changes = changes_[i];
        if (changes.empty() || changes.back().value != value) changes.push_back({sample, value});
    }
}

std::size_t Trace::Find(const std::string& path) const {
    for (std::size_t i = 0; i < signals_.size(); ++i) {
        if (signals_[i].path == path) return i;
    }
    throw std::out_of_range("Trace: no signal " + path);
}

TraceValue Trace::ValueAt(std::size_t signal, std::size_t sample) const {
    if (sample >= times_.size()) throw std::out_of_range("Trace: no such sample");
    const auto& changes = changes_.at(signal);
    const auto after = std::upper_bound(changes.begin(), changes.end(), sample,
                                        [](std::size_t s, const Change& change) { return s < change.sample; });
    return std::prev(after)->value;  // the first change is sample 0
}

}  // namespace pac
