// The keys of every object a scenario file holds, in one table: the loader allows exactly these
// (json::Object refuses any other), and scenario/scenario.schema.json lists the same ones as the
// properties of the definition of the same name, which tests/scenario checks key by key.
#pragma once

#include <string>
#include <vector>

namespace pac::scenario::keys {

struct ObjectKeys {
    std::string definition;         // the schema's definition: "timing", "commandStep", ...
    std::vector<std::string> keys;  // in the order the docs list them
};

// Every object of the format, the top level first ("scenario").
const std::vector<ObjectKeys>& All();
// The keys of `definition`; std::out_of_range for a definition the table does not have.
const std::vector<std::string>& Of(const std::string& definition);
// The definitions of the kinds of step (a step is exactly one of them).
const std::vector<std::string>& StepDefinitions();
// Every key any kind of step may have: what a step with no kind is checked against.
std::vector<std::string> AnyStep();

}  // namespace pac::scenario::keys
