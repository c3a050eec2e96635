"""JUnit XML, the form GitLab, Jenkins and GitHub read (Ant's junit task, Jenkins' junit-10.xsd): one
testsuites root holding one testsuite, one testcase per test run, a failure element per failed test and a
skipped element for an expected failure."""
import datetime
import socket
from xml.sax.saxutils import quoteattr, escape


def write(path, suite, results, seconds):
    failures = sum(1 for r in results if r.outcome in ("failed", "passed unexpectedly"))
    errors = sum(1 for r in results if r.outcome == "error")
    skipped = sum(1 for r in results if r.outcome == "failed as expected")
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%S")
    counts = f'tests="{len(results)}" failures="{failures}" errors="{errors}" skipped="{skipped}" time="{seconds:.3f}"'
    lines = ['<?xml version="1.0" encoding="UTF-8"?>', f'<testsuites name={quoteattr("pac-test")} {counts}>',
             f'  <testsuite name={quoteattr(suite)} {counts} timestamp="{stamp}" '
             f'hostname={quoteattr(socket.gethostname())} id="0" package={quoteattr(suite)}>']
    for r in results:
        lines.append(f'    <testcase name={quoteattr(r.name)} classname={quoteattr(suite)} time="{r.seconds:.3f}" '
                     f'assertions="{r.asserts}">')
        text = "\n".join(r.lines)
        first = r.lines[0] if r.lines else r.outcome
        if r.outcome in ("failed", "passed unexpectedly"):
            lines.append(f'      <failure message={quoteattr(first)} type="assert">{escape(text)}</failure>')
        elif r.outcome == "error":
            lines.append(f'      <error message={quoteattr(first)} type="host">{escape(text)}</error>')
        elif r.outcome == "failed as expected":
            lines.append(f'      <skipped message={quoteattr("expected failure: " + first)}/>')
        if r.vcd:
            lines.append(f'      <system-out>{escape("VCD: " + r.vcd)}</system-out>')
        lines.append('    </testcase>')
    lines += ['  </testsuite>', '</testsuites>', '']
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))
