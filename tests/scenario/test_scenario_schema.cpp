// scenario/scenario.schema.json and the loader say the same: each object of the format has in the schema
// exactly the keys the loader allows (scenario_keys), with "additionalProperties": false, and no object
// the loader does not know; the names the schema offers editors are exactly the ones the loader takes,
// compiled in from GVL_PAC and the ST enumerations. tests/scenario/schema_check.py checks the files of
// the tree under the schema and damages them place by place against both.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pac/enum_names.hpp"
#include "pac/gvl_table.hpp"
#include "scenario.hpp"
#include "scenario_keys.hpp"

namespace {

using Json = nlohmann::json;
using Names = std::set<std::string>;

const Json& Schema() {
    static const Json schema = [] {
        std::ifstream in(std::string(PAC_SCENARIO_DIR) + "/scenario.schema.json");
        return Json::parse(in);
    }();
    return schema;
}

// The schema of an object of the format: the top level for "scenario", else its definition.
const Json& Definition(const std::string& name) {
    return name == "scenario" ? Schema() : Schema().at("definitions").at(name);
}

Names PropertyNames(const Json& object) {
    Names names;
    for (const auto& item : object.at("properties").items()) names.insert(item.key());
    return names;
}

// The values of the `enum` among the alternatives (anyOf / oneOf) of `definition`, or of its own `enum`.
Names EnumOf(const Json& definition) {
    Names names;
    auto add = [&names](const Json& schema) {
        if (!schema.contains("enum")) return;
        for (const Json& value : schema.at("enum")) {
            if (value.is_string()) names.insert(value.get<std::string>());
        }
    };
    add(definition);
    for (const char* alternatives : {"anyOf", "oneOf"}) {
        if (definition.contains(alternatives)) {
            for (const Json& schema : definition.at(alternatives)) add(schema);
        }
    }
    return names;
}

Names GvlNamesWith(const std::vector<std::string>& prefixes) {
    Names names;
    for (const PACST_CONSTANT& constant : pac::GvlTable::GvlPac()) {
        const std::string name = constant.name;
        for (const std::string& prefix : prefixes) {
            if (name.rfind(prefix, 0) == 0) names.insert(name);
        }
    }
    return names;
}

// Empty when the schema and the loader have the same names; else what each has alone (what to add where).
std::string Disagreement(const Names& schema, const Names& loader) {
    std::string text;
    auto only = [&text](const Names& a, const Names& b, const char* where) {
        std::string names;
        for (const std::string& name : a) {
            if (!b.count(name)) names += " " + name;
        }
        if (!names.empty()) text += std::string(where) + ":" + names + "; ";
    };
    only(schema, loader, "only in scenario.schema.json");
    only(loader, schema, "only in the loader (add them to scenario.schema.json)");
    return text;
}

Names Union(Names a, const std::vector<std::string>& b) {
    a.insert(b.begin(), b.end());
    return a;
}

TEST(ScenarioSchema, EveryObjectHasTheLoadersKeysAndNoOther) {
    Names loaderObjects;
    for (const auto& object : pac::scenario::keys::All()) {
        SCOPED_TRACE(object.definition);
        loaderObjects.insert(object.definition);
        const Json& definition = Definition(object.definition);
        EXPECT_EQ(Disagreement(PropertyNames(definition), Names(object.keys.begin(), object.keys.end())), "");
        EXPECT_EQ(definition.value("additionalProperties", true), false) << "an unknown key must be refused";
        EXPECT_EQ(definition.at("type"), "object");
    }
    for (const auto& item : Schema().at("definitions").items()) {
        if (item.value().contains("properties")) {
            EXPECT_TRUE(loaderObjects.count(item.key())) << "the schema's object " << item.key() << " is no loader's";
        }
    }
}

TEST(ScenarioSchema, StepsAreTheLoadersKindsEachWithItsKey) {
    Names alternatives;
    for (const Json& step : Schema().at("definitions").at("step").at("oneOf")) {
        const std::string ref = step.at("$ref");
        alternatives.insert(ref.substr(ref.rfind('/') + 1));
    }
    const auto& kinds = pac::scenario::keys::StepDefinitions();
    EXPECT_EQ(Disagreement(alternatives, Names(kinds.begin(), kinds.end())), "");
    Names faults;
    for (const std::string& name : kinds) {
        // The kind's key (the first of the loader's keys: "command", ..., "fault", "wait_ms") is required.
        const Json& required = Definition(name).at("required");
        EXPECT_NE(std::find(required.begin(), required.end(), pac::scenario::keys::Of(name).front()), required.end())
            << name;
        const Json fault = Definition(name).at("properties").value("fault", Json::object());
        if (fault.contains("const")) faults.insert(fault.at("const").get<std::string>());
        for (const std::string value : fault.value("enum", Json::array())) faults.insert(value);
    }
    Names loaderFaults;
    for (auto kind = 0; kind <= static_cast<int>(pac::scenario::FaultKind::kSetInput); ++kind) {
        loaderFaults.insert(pac::scenario::ToString(static_cast<pac::scenario::FaultKind>(kind)));
    }
    EXPECT_EQ(Disagreement(faults, loaderFaults), "");
}

TEST(ScenarioSchema, NamesAreTheOnesTheLoaderTakes) {
    const Json& definitions = Schema().at("definitions");
    EXPECT_EQ(Disagreement(EnumOf(definitions.at("commandCode")), GvlNamesWith({"PAC_CMD_"})), "");
    EXPECT_EQ(Disagreement(EnumOf(definitions.at("errorId")), GvlNamesWith({"PAC_ERR_", "PAC_LIB_ERR_"})), "");
    EXPECT_EQ(Disagreement(EnumOf(definitions.at("operatingStatus")), GvlNamesWith({"PAC_STATUS_"})), "");
    Names statusValues;
    for (const Json& alternative : definitions.at("operatingStatus").at("anyOf")) {
        for (const Json& value : alternative.at("enum")) {
            if (value.is_number()) statusValues.insert(std::to_string(value.get<int>()));
        }
    }
    Names gvlStatusValues;
    for (const PACST_CONSTANT& constant : pac::GvlTable::GvlPac()) {
        if (std::string(constant.name).rfind("PAC_STATUS_", 0) == 0) {
            gvlStatusValues.insert(std::to_string(constant.value));
        }
    }
    EXPECT_EQ(Disagreement(statusValues, gvlStatusValues), "");
    EXPECT_EQ(EnumOf(Definition("ctrlStep").at("properties").at("ctrl")),
              Union({}, pac::EnumNames(E_PAC_CTRLREQUEST__NAMES).All()));
    EXPECT_EQ(EnumOf(Definition("axisJob").at("properties").at("command")),
              Union(Union({}, pac::EnumNames(E_PAC_AXISCOMMAND__NAMES).All()), pac::scenario::McCommandNames()));
    EXPECT_EQ(EnumOf(Definition("axisJob").at("properties").at("condition")),
              Union({}, pac::EnumNames(E_PAC_MOVECONDITION__NAMES).All()));
}

}  // namespace
