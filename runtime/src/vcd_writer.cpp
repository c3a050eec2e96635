// A Trace as a Value Change Dump (see vcd_writer.hpp).
#include "pac/vcd_writer.hpp"

#include <cstdio>
#include <memory>
#include <vector>

namespace pac {

namespace {

// Identifier codes of the printable ASCII characters '!'..'~', as short as the count allows.
std::string IdentifierCode(std::size_t index) {
    constexpr std::size_t kFirst = 33, kCount = 94;
    std::string code;
    do {
        code += static_cast<char>(kFirst + index % kCount);
        index /= kCount;
    } while (index > 0);
    return code;
}

std::string Binary(std::uint64_t bits) {
    std::string text;
    do {
        text.insert(text.begin(), (bits & 1U) ? '1' : '0');
        bits >>= 1U;
    } while (bits != 0);
    return text;
}

std::string ValueText(const SignalInfo& signal, const TraceValue& value, const std::string& code) {
    if (signal.kind == SignalKind::kReal) {
        char text[40];
        std::snprintf(text, sizeof text, "r%.17g ", value.real);  // round-trips every double
        return text + code;
    }
    if (signal.width == 1) return (value.bits ? "1" : "0") + code;
    return "b" + Binary(value.bits) + " " + code;
}

// The scopes as a tree, children and signals in the order they first appear.
struct Scope {
    std::string name;
    std::vector<std::unique_ptr<Scope>> children;
    std::vector<std::size_t> signals;

    Scope& Child(const std::string& childName) {
        for (auto& child : children) {
            if (child->name == childName) return *child;
        }
        children.push_back(std::make_unique<Scope>());
        children.back()->name = childName;
        return *children.back();
    }
};

Scope BuildScopes(const Trace& trace, const std::string& top) {
    Scope root;
    root.name = top;
    for (std::size_t i = 0; i < trace.Signals().size(); ++i) {
        Scope* scope = &root;
        const std::string path = trace.Signals()[i].Scope();
        std::size_t start = 0;
        while (!path.empty() && start <= path.size()) {
            const auto dot = path.find('.', start);
            const auto end = dot == std::string::npos ? path.size() : dot;
            scope = &scope->Child(path.substr(start, end - start));
            start = end + 1;
        }
        scope->signals.push_back(i);
    }
    return root;
}

void WriteScope(const Scope& scope, const Trace& trace, std::ostream& out) {
    out << "$scope module " << scope.name << " $end\n";
    for (std::size_t i : scope.signals) {
        const SignalInfo& signal = trace.Signals()[i];
        out << "$var " << (signal.kind == SignalKind::kReal ? "real" : "wire") << " " << signal.width << " "
            << IdentifierCode(i) << " " << signal.Name() << " $end\n";
    }
    for (const auto& child : scope.children) WriteScope(*child, trace, out);
    out << "$upscope $end\n";
}

}  // namespace

void WriteVcd(const Trace& trace, std::ostream& out, const VcdOptions& options) {
    if (!options.comment.empty()) out << "$comment " << options.comment << " $end\n";
    out << "$version PA-CONTROL PLC library trace (pac::WriteVcd) $end\n"
        << "$timescale 1 ns $end\n";
    WriteScope(BuildScopes(trace, options.top), trace, out);
    out << "$enddefinitions $end\n";
    const auto& signals = trace.Signals();
    std::vector<std::size_t> next(signals.size(), 0);  // each signal's next change
    bool stamped = false;
    for (std::size_t sample = 0; sample < trace.Samples(); ++sample) {
        stamped = false;
        for (std::size_t i = 0; i < signals.size(); ++i) {
            const auto& changes = trace.Changes(i);
            if (next[i] >= changes.size() || changes[next[i]].sample != sample) continue;
            if (!stamped) {
                out << "#" << trace.TimeOf(sample).count() << "\n" << (sample == 0 ? "$dumpvars\n" : "");
                stamped = true;
            }
            out << ValueText(signals[i], changes[next[i]++].value, IdentifierCode(i)) << "\n";
        }
        if (sample == 0 && stamped) out << "$end\n";
    }
    // A viewer ends the waveform at the last time stamp: without one for the last sample, the scans
    // after the last change would be cut off.
    if (trace.Samples() > 0 && !stamped) out << "#" << trace.TimeOf(trace.Samples() - 1).count() << "\n";
}

}  // namespace pac
