#include "wavejson_writer.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "pac/format_time.hpp"
#include "text_format.hpp"

namespace pac::scenario {

namespace {

using Json = nlohmann::ordered_json;

constexpr std::size_t kGap = static_cast<std::size_t>(-1);  // a column that stands for skipped scans

// A lane of the diagram: a signal, or for a module's bytes, four of them (a text of 8 bytes does not fit a
// few scans' width).
struct LaneSpec {
    std::size_t signal;
    std::string name;
    int firstByte = 0;  // kBytes: the bytes shown, counted from the signal's most significant
    int bytes = 0;
};

constexpr int kBytesPerLane = 4;
constexpr std::size_t kGroupLanes = 3;  // fewer lanes leave no room for the group's name

std::string LastPart(const std::string& scope) {
    const auto dot = scope.rfind('.');
    return dot == std::string::npos ? scope : scope.substr(dot + 1);
}

std::string ValueText(const SignalInfo& signal, ValueFormat format, const TraceValue& value, const LaneSpec& lane) {
    char text[64];
    switch (format) {
        case ValueFormat::kReal:
            std::snprintf(text, sizeof text, "%.3f", value.real);
            return text;
        case ValueFormat::kDecimal:
            return std::to_string(value.bits);
        case ValueFormat::kErrorId:
            return ErrorIdText(static_cast<std::uint16_t>(value.bits));
        case ValueFormat::kBytes: {
            std::string bytes;
            for (int byte = lane.firstByte; byte < lane.firstByte + lane.bytes; ++byte) {
                const int shift = signal.width - 8 * (byte + 1);
                std::snprintf(text, sizeof text, "%s%02X", bytes.empty() ? "" : " ",
                              static_cast<unsigned>(value.bits >> shift & 0xFFU));
                bytes += text;
            }
            return bytes;
        }
        case ValueFormat::kBit:
            return value.bits ? "1" : "0";
        case ValueFormat::kHex:
            break;
    }
    std::snprintf(text, sizeof text, "%0*" PRIX64, (signal.width + 3) / 4, value.bits);
    return text;
}

// The columns: every scan where a lane that is not sampled changes, runs of up to maxIdle other scans in
// full, longer ones as their first scan and a gap; after the last change, at most maxIdle scans.
std::vector<std::size_t> Columns(const Trace& trace, const std::vector<std::size_t>& lanes, const WaveJsonRequest& r) {
    std::vector<std::size_t> keys;  // the lanes whose changes keep a scan
    for (std::size_t lane : lanes) {
        const SignalInfo& signal = trace.Signals()[lane];
        if (signal.kind == SignalKind::kBits &&
            std::find(r.sampled.begin(), r.sampled.end(), signal.path) == r.sampled.end()) {
            keys.push_back(lane);
        }
    }
    auto changed = [&](std::size_t s) {
        return std::any_of(keys.begin(), keys.end(),
                           [&](std::size_t lane) { return trace.ValueAt(lane, s) != trace.ValueAt(lane, s - 1); });
    };
    std::vector<std::size_t> columns{r.begin};
    std::vector<std::size_t> idle;
    for (std::size_t s = r.begin + 1; s < r.end; ++s) {
        if (!changed(s)) {
            idle.push_back(s);
            continue;
        }
        if (idle.size() <= static_cast<std::size_t>(r.maxIdleScans)) {
            columns.insert(columns.end(), idle.begin(), idle.end());
        } else {
            // The first scan of the run stays, so a value that changed just before is not centred on the gap.
            columns.push_back(idle.front());
            columns.push_back(kGap);
        }
        idle.clear();
        columns.push_back(s);
    }
    const auto tail = std::min(idle.size(), static_cast<std::size_t>(r.maxIdleScans));
    columns.insert(columns.end(), idle.begin(), idle.begin() + static_cast<std::ptrdiff_t>(tail));
    return columns;
}

// A lane over the columns: a wave of '0', '1' and '.' for a bit, for anything else data ('=' and the
// text, '.' while it stays).
Json Lane(const std::string& name, const std::vector<std::size_t>& columns, bool bit,
          const std::function<std::string(std::size_t)>& textOf) {
    std::string wave;
    Json data = Json::array();
    std::optional<std::string> last;
    for (std::size_t column : columns) {
        if (column == kGap) {
            wave += '|';
            // Data is written again after a gap: centred on a segment across the gap, its text would sit on
            // the gap's mark.
            if (!bit) last.reset();
            continue;
        }
        const std::string text = textOf(column);
        if (last && *last == text) {
            wave += '.';
        } else if (bit) {
            wave += text;
        } else {
            wave += '=';
            data.push_back(text);
        }
        last = text;
    }
    Json lane = {{"name", name}, {"wave", wave}};
    if (!data.empty()) lane["data"] = data;
    return lane;
}

}  // namespace

void WriteWaveJson(const Trace& trace, const std::function<ValueFormat(const std::string&)>& formatOf,
                   const WaveJsonRequest& request, std::ostream& out) {
    if (request.end > trace.Samples() || request.begin > request.end) throw std::out_of_range("WaveJSON: window outside the trace");
    if (request.begin == request.end) throw std::invalid_argument("WaveJSON: the window holds no scan");
    std::vector<std::size_t> lanes;
    std::vector<LaneSpec> specs;
    for (const auto& path : request.lanes) {
        const std::size_t signal = trace.Find(path);
        lanes.push_back(signal);
        const SignalInfo& info = trace.Signals()[signal];
        const int bytes = info.width / 8;
        if (formatOf(path) != ValueFormat::kBytes || bytes <= kBytesPerLane) {
            specs.push_back({signal, info.Name(), 0, bytes});
            continue;
        }
        for (int first = 0; first < bytes; first += kBytesPerLane) {
            const int count = std::min(kBytesPerLane, bytes - first);
            specs.push_back({signal, info.Name() + " " + std::to_string(first) + ".." + std::to_string(first + count - 1),
                             first, count});
        }
    }
    const auto columns = Columns(trace, lanes, request);

    std::vector<Json> rows;  // lanes and groups of lanes, in order
    rows.push_back(Lane("t [ms]", columns, false, [&trace](std::size_t s) { return pac::FormatMsNumber(trace.TimeOf(s)); }));
    // At least kGroupLanes neighbouring lanes of one scope form a group named after the scope's last part;
    // a name two lanes share is written with that part in front ("cmd.Status", "ctrl.Status").
    std::vector<std::string> scopes;
    for (const LaneSpec& spec : specs) scopes.push_back(LastPart(trace.Signals()[spec.signal].Scope()));
    std::vector<bool> grouped(specs.size(), false);
    for (std::size_t i = 0, run = 1; i < specs.size(); i += run) {
        for (run = 1; i + run < specs.size() && scopes[i + run] == scopes[i]; ++run) {
        }
        if (run >= kGroupLanes && !scopes[i].empty()) std::fill_n(grouped.begin() + static_cast<std::ptrdiff_t>(i), run, true);
    }
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const LaneSpec& spec = specs[i];
        const SignalInfo& signal = trace.Signals()[spec.signal];
        const ValueFormat format = formatOf(signal.path);
        const bool shared = std::count_if(specs.begin(), specs.end(), [&](const LaneSpec& other) { return other.name == spec.name; }) > 1;
        Json row = Lane(shared && !scopes[i].empty() ? scopes[i] + "." + spec.name : spec.name, columns,
                        format == ValueFormat::kBit,
                        [&](std::size_t s) { return ValueText(signal, format, trace.ValueAt(spec.signal, s), spec); });
        if (!grouped[i]) {
            rows.push_back(row);
        } else if (i > 0 && grouped[i - 1] && scopes[i - 1] == scopes[i]) {
            rows.back().push_back(row);
        } else {
            rows.push_back(Json::array({scopes[i], row}));
        }
    }

    // One lane per line, so a change to a diagram reads well in a diff.
    out << "{\"signal\": [\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].is_array()) {
            out << "  [" << rows[i][0].dump() << ",\n";
            for (std::size_t k = 1; k < rows[i].size(); ++k) {
                out << "    " << rows[i][k].dump() << (k + 1 < rows[i].size() ? ",\n" : "\n");
            }
            out << "  ]";
        } else {
            out << "  " << rows[i].dump();
        }
        out << (i + 1 < rows.size() ? ",\n" : "\n");
    }
    out << "],\n \"head\": " << Json{{"text", request.title}}.dump() << ",\n \"foot\": "
        << Json{{"text", request.foot}}.dump() << ",\n \"config\": " << Json{{"hscale", request.hscale}}.dump() << "}\n";
}

}  // namespace pac::scenario
