#include "json_fields.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <set>

namespace pac::scenario::json {

namespace {

bool IsIdentifier(const std::string& key) {
    if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
    return std::all_of(key.begin(), key.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Follows the parser's events to know where it is, so a duplicate key is refused with its path.
class DuplicateKeyFinder {
public:
    bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
        using Event = Json::parse_event_t;
        switch (event) {
            case Event::object_start:
            case Event::array_start:
                CountElement();
                frames_.push_back({event == Event::array_start, 0, "", {}});
                break;
            case Event::object_end:
            case Event::array_end:
                if (!frames_.empty()) frames_.pop_back();
                break;
            case Event::key: {
                Frame& top = frames_.back();
                top.key = parsed.get<std::string>();
                if (!top.keys.insert(top.key).second && !duplicate_) duplicate_ = ScenarioError(Path(), "duplicate key " + Quoted(top.key));
                break;
            }
            case Event::value:
                CountElement();
                break;
        }
        return true;
    }

    const std::optional<ScenarioError>& Duplicate() const { return duplicate_; }

private:
    struct Frame {
        bool isArray;
        std::size_t next;  // arrays: the index the next element gets
        std::string key;   // objects: the key being read
        std::set<std::string> keys;
    };

    void CountElement() {
        if (!frames_.empty() && frames_.back().isArray) ++frames_.back().next;
    }

    std::string Path() const {
        std::string path = "$";
        for (const Frame& frame : frames_) path = frame.isArray ? Element(path, frame.next - 1) : Child(path, frame.key);
        return path;
    }

    std::vector<Frame> frames_;
    std::optional<ScenarioError> duplicate_;
};

}  // namespace

Json Parse(const std::string& text) {
    DuplicateKeyFinder finder;
    Json document;
    try {
        document = Json::parse(text, std::ref(finder));
    } catch (const nlohmann::json::exception& e) {
        std::string message = e.what();
        const auto end = message.find("] ");
        if (message.rfind("[json.exception.", 0) == 0 && end != std::string::npos) message.erase(0, end + 2);
        throw ScenarioError("", "not valid JSON: " + message);
    }
    if (finder.Duplicate()) throw *finder.Duplicate();
    return document;
}

std::string Child(const std::string& path, const std::string& key) {
    return IsIdentifier(key) ? path + "." + key : path + "[" + Quoted(key) + "]";
}

std::string Element(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

std::string Describe(const Json& value) {
    switch (value.type()) {
        case Json::value_t::object:
            return "an object";
        case Json::value_t::array:
            return "an array";
        case Json::value_t::string: {
            std::string text = value.get<std::string>();
            if (text.size() > 40) text = text.substr(0, 37) + "...";
            return "a string " + Quoted(text);
        }
        case Json::value_t::boolean:
            return value.get<bool>() ? "true" : "false";
        case Json::value_t::null:
            return "null";
        default:
            return "the number " + value.dump();
    }
}

void Refuse(const std::string& path, const std::string& reason) { throw ScenarioError(path, reason); }

void RefuseType(const std::string& path, const std::string& expected, const Json& value) {
    Refuse(path, "wrong type: expected " + expected + ", got " + Describe(value));
}

void RequireObject(const Json& value, const std::string& path) {
    if (!value.is_object()) RefuseType(path, "an object", value);
}

std::string ListKeys(const std::vector<std::string>& keys, const std::string& conjunction) {
    std::string list;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (i > 0) list += i + 1 == keys.size() ? " " + conjunction + " " : ", ";
        list += Quoted(keys[i]);
    }
    return list;
}

Object::Object(const Json& value, std::string path, std::vector<std::string> allowed, const std::string& what)
    : value_(value), path_(std::move(path)), what_(what) {
    RequireObject(value_, path_);
    for (const auto& item : value_.items()) {
        if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end()) {
            Refuse(Child(path_, item.key()),
                   "unknown key " + Quoted(item.key()) + " (" + what_ + " has " + ListKeys(allowed) + ")");
        }
    }
}

const Json* Object::Find(const std::string& key) const {
    const auto it = value_.find(key);
    return it == value_.end() ? nullptr : &*it;
}

const Json& Object::Get(const std::string& key) const {
    const Json* value = Find(key);
    if (value == nullptr) Refuse(path_, "missing key " + Quoted(key) + " (" + what_ + " needs it)");
    return *value;
}

std::int64_t Integer(const Json& value, const std::string& path, std::int64_t min, std::int64_t max) {
    const std::string range = " is not in " + std::to_string(min) + ".." + std::to_string(max);
    if (value.is_number_unsigned()) {
        const auto number = value.get<std::uint64_t>();
        if (number > static_cast<std::uint64_t>(max) || (min > 0 && number < static_cast<std::uint64_t>(min))) {
            Refuse(path, "out of range: " + value.dump() + range);
        }
        return static_cast<std::int64_t>(number);
    }
    if (value.is_number_integer()) {
        const auto number = value.get<std::int64_t>();
        if (number < min || number > max) Refuse(path, "out of range: " + value.dump() + range);
        return number;
    }
    if (value.is_number_float()) {
        const double number = value.get<double>();
        if (!std::isfinite(number) || std::trunc(number) != number) RefuseType(path, "an integer", value);
        if (number < static_cast<double>(min) || number > static_cast<double>(max)) {
            Refuse(path, "out of range: " + value.dump() + range);
        }
        return static_cast<std::int64_t>(number);
    }
    RefuseType(path, "an integer", value);
}

std::uint64_t Unsigned(const Json& value, const std::string& path) {
    if (value.is_number_unsigned()) return value.get<std::uint64_t>();
    if (value.is_number_integer() || value.is_number_float()) {
        const double number = value.get<double>();
        if (value.is_number_float() && (!std::isfinite(number) || std::trunc(number) != number)) {
            RefuseType(path, "an integer", value);
        }
        if (number < 0 || number >= 18446744073709551616.0) {
            Refuse(path, "out of range: " + value.dump() + " is not in 0..18446744073709551615");
        }
        return static_cast<std::uint64_t>(number);
    }
    RefuseType(path, "an integer", value);
}

double Number(const Json& value, const std::string& path) {
    if (!value.is_number()) RefuseType(path, "a number", value);
    return value.get<double>();
}

bool Bool(const Json& value, const std::string& path) {
    if (!value.is_boolean()) RefuseType(path, "true or false", value);
    return value.get<bool>();
}

std::string String(const Json& value, const std::string& path) {
    if (!value.is_string()) RefuseType(path, "a string", value);
    return value.get<std::string>();
}

std::string Quoted(const std::string& text) { return Json(text).dump(); }

int Duration(const Object& object, const std::string& key, int fallback) {
    const Json* value = object.Find(key);
    return value ? static_cast<int>(Integer(*value, object.PathOf(key), 1, kMaxDurationMs)) : fallback;
}

}  // namespace pac::scenario::json
