// Path-aware reading of a JSON document, for ScenarioLoader: every refusal is a ScenarioError naming
// the JSONPath of the value ($.steps[2].param, indices from 0) and the reason, in one of these forms:
//   not valid JSON: ..., duplicate key "k", unknown key "k" (allowed: ...), missing key "k",
//   wrong type: expected an integer, got a string "3", out of range: 70000 is not in 0..65535.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario_error.hpp"

namespace pac::scenario::json {

using Json = nlohmann::ordered_json;  // keeps the file's key order, so the first bad key is reported

// Parses `text`; refuses invalid JSON (with line and column) and an object with a key twice.
Json Parse(const std::string& text);

std::string Child(const std::string& path, const std::string& key);  // $.timing, $.n_registers["3"]
std::string Element(const std::string& path, std::size_t index);     // $.steps[2]

// "a string \"abc\"", "an integer 5", "an array", ...: what a value is, for messages.
std::string Describe(const Json& value);

[[noreturn]] void Refuse(const std::string& path, const std::string& reason);
[[noreturn]] void RefuseType(const std::string& path, const std::string& expected, const Json& value);

// An object whose keys must all be among `allowed`. `what` names it in messages ("a step").
class Object {
public:
    Object(const Json& value, std::string path, std::vector<std::string> allowed, const std::string& what);

    bool Has(const std::string& key) const { return value_.contains(key); }
    const Json* Find(const std::string& key) const;
    const Json& Get(const std::string& key) const;  // refused as a missing key if absent
    std::string PathOf(const std::string& key) const { return Child(path_, key); }
    const std::string& Path() const { return path_; }

private:
    const Json& value_;
    std::string path_;
    std::string what_;
};

// Refuses unless `value` is an object (its keys are checked by the caller).
void RequireObject(const Json& value, const std::string& path);
// Keys as a message lists them: "a", "b" or "c" (or with another conjunction: "a" and "b").
std::string ListKeys(const std::vector<std::string>& keys, const std::string& conjunction = "or");

// Integers accept a JSON integer or a number with no fraction (2.0).
std::int64_t Integer(const Json& value, const std::string& path, std::int64_t min, std::int64_t max);
std::uint64_t Unsigned(const Json& value, const std::string& path);
double Number(const Json& value, const std::string& path);
bool Bool(const Json& value, const std::string& path);
std::string String(const Json& value, const std::string& path);

// "abc" with JSON's quotes and escapes, for messages.
std::string Quoted(const std::string& text);

// The longest wait, timeout or end timeout a scenario may ask for: one hour.
constexpr int kMaxDurationMs = 3'600'000;
// The duration `key` of `object` in ms, 1..kMaxDurationMs, or `fallback` when it is absent.
int Duration(const Object& object, const std::string& key, int fallback);

}  // namespace pac::scenario::json
