#include "expectations.hpp"

#include <cmath>
#include <cstdio>

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

std::vector<std::string> CheckAxisExpectation(const AxisJob& job, const AxisOutcome& outcome) {
    std::vector<std::string> failures;
    const AxisExpectation& expect = job.expect;
    if (!outcome.finished) {
        const std::string what = job.HasJob()      ? "neither Done, Error nor CommandAborted"
                                 : job.resetError ? "AxisError still set"
                                                  : "Enabled did not follow Enable";
        failures.push_back(what + " within " + std::to_string(job.maxMs) + " ms");
        return failures;
    }
    auto flag = [&failures](const char* name, const std::optional<bool>& expected, bool actual) {
        if (expected && *expected != actual) {
            failures.push_back(std::string(name) + " is " + Bool(actual) + ", expected " + Bool(*expected));
        }
    };
    flag("Done", expect.done, outcome.done);
    flag("Error", expect.error, outcome.error);
    flag("CommandAborted", expect.aborted, outcome.aborted);
    flag("Referenced", expect.referenced, outcome.referenced);
    if (expect.errorId && *expect.errorId != outcome.errorId) {
        failures.push_back("ErrorID is " + ErrorIdText(outcome.errorId) + ", expected " + ErrorIdText(*expect.errorId));
    }
    if (expect.position && !(std::fabs(outcome.position - *expect.position) <= expect.positionTolerance)) {
        char text[160];
        std::snprintf(text, sizeof text, "ActualPosition is %.4f, expected %.4f +- %g", outcome.position,
                      *expect.position, expect.positionTolerance);
        failures.push_back(text);
    }
    return failures;
}

}  // namespace pac::scenario
