#include "expectations.hpp"

#include "text_format.hpp"

namespace pac::scenario {

namespace {

const char* Bool(bool value) { return value ? "TRUE" : "FALSE"; }

}  // namespace

std::vector<std::string> CheckExpectation(const Expectation& expect, const CommandOutcome& outcome) {
    std::vector<std::string> failures;
    if (!outcome.finished) {
        failures.push_back("neither Done nor Error within " + std::to_string(outcome.endScan - outcome.edgeScan) +
                           " scans");
        return failures;
    }
    if (expect.done && *expect.done != outcome.done) {
        failures.push_back(std::string("Done is ") + Bool(outcome.done) + ", expected " + Bool(*expect.done));
    }
    if (expect.error && *expect.error != outcome.error) {
        failures.push_back(std::string("Error is ") + Bool(outcome.error) + ", expected " + Bool(*expect.error));
    }
    if (expect.errorId && *expect.errorId != outcome.errorId) {
        failures.push_back("ErrorID is " + ErrorIdText(outcome.errorId) + ", expected " + ErrorIdText(*expect.errorId));
    }
    if (expect.ackData && expect.ackData->bits != outcome.ackData) {
        failures.push_back("AckData is " + DwordText(outcome.ackData, expect.ackData->isReal) + ", expected " +
                           DwordText(*expect.ackData));
    }
    return failures;
}

}  // namespace pac::scenario
