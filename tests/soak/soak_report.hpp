// What a soak run found: counts for the summary line and the first violations in words. A violation is
// anything the library must never do; the soak's exit code is 1 if there was one.
#pragma once

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

namespace pac::soak {

class SoakReport {
public:
    void Violation(std::int64_t scan, const std::string& what) {
        ++violations_;
        if (messages_.size() < kKept) messages_.push_back("scan " + std::to_string(scan) + ": " + what);
    }
    std::int64_t Violations() const { return violations_; }
    void Print(std::ostream& out) const {
        for (const std::string& m : messages_) out << "violation: " << m << "\n";
        if (violations_ > static_cast<std::int64_t>(messages_.size())) {
            out << "(" << violations_ - static_cast<std::int64_t>(messages_.size()) << " more violations)\n";
        }
    }

private:
    static constexpr std::size_t kKept = 20;
    std::int64_t violations_ = 0;
    std::vector<std::string> messages_;
};

}  // namespace pac::soak
