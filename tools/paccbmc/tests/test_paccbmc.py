"""paccbmc on CBMC output written out by hand: the verdict (properties hold, reachability checks reached,
known open failures) and the counterexample table."""
import json
import unittest

from paccbmc import cli, results, timeline


def _assign(lhs, data, hidden=False):
    return {"stepType": "assignment", "lhs": lhs, "hidden": hidden, "value": {"data": data}}


TRACE = [
    _assign("tl_scan", "0", hidden=True),  # the globals' zero initialisation: no row
    _assign("tl_a_busy", "TRUE"), _assign("return_value_nondet_bool", "TRUE"),
    _assign("tl_to_pac", "0x1122334455667788ull"), _assign("tl_a_errorid", "32769"), _assign("tl_scan", "1"),
    _assign("return_value_nondet_uchar", "7"), _assign("tl_a_busy", "FALSE"), _assign("tl_scan", "2"),
    {"stepType": "failure", "property": "main.assertion.1"},
]


def _output(*props):
    return json.dumps([{"program": "CBMC 6.6.0"},
                       {"result": [{"property": n, "description": d, "status": s, "trace": TRACE} for n, d, s in props]}])


class Verdict(unittest.TestCase):
    def test_reach_must_fail_and_properties_must_hold(self):
        props = results.parse(_output(("a", "P1 exclusive", "SUCCESS"), ("b", "reach: Done", "FAILURE"),
                                      ("c", "reach: Error", "SUCCESS"), ("d", "P5 Done", "FAILURE")))
        verdict = results.judge(props)
        self.assertFalse(verdict.ok)
        self.assertEqual([p.name for p in verdict.failed], ["d"])
        self.assertEqual([p.name for p in verdict.unreached], ["c"])
        self.assertEqual((verdict.held, verdict.reached), (1, 1))

    def test_known_open_failure_does_not_fail_the_run(self):
        props = results.parse(_output(("d", "P5 Done", "FAILURE"), ("b", "reach: Done", "FAILURE")))
        verdict = results.judge(props, known_open=["P5 "])
        self.assertTrue(verdict.ok)
        self.assertEqual([p.name for p in verdict.known_open], ["d"])

    def test_unknown_status_fails(self):
        verdict = results.judge(results.parse(_output(("a", "P1", "UNKNOWN"))))
        self.assertFalse(verdict.ok)

    def test_errors_without_results_are_reported(self):
        with self.assertRaises(ValueError):
            results.parse(json.dumps([{"messageType": "ERROR", "messageText": "parse error"}]))


class Timeline(unittest.TestCase):
    def test_one_row_per_scan_values_kept(self):
        rows = timeline.rows(TRACE)
        self.assertEqual([r["scan"] for r in rows], [1, 2])
        self.assertEqual(rows[1]["a_errorid"], 32769)  # kept from the row before
        self.assertEqual(rows[1]["a_busy"], 0)

    def test_table_shows_bytes_and_codes_in_hex(self):
        text = timeline.table(TRACE)
        self.assertIn("11 22 33 44 55 66 77 88", text)
        self.assertIn("8001", text)
        self.assertEqual(len(text.splitlines()), 3)  # header and two scans

    def test_free_inputs_in_order(self):
        self.assertEqual(timeline.nondet_values(TRACE), [1, 7])


if __name__ == "__main__":
    unittest.main()


class TimelineRerun(unittest.TestCase):
    def test_failed_properties_checked_again_without_slicing(self):
        failed = [results.Property("main.assertion.3", "P5 Done", "FAILURE")]
        self.assertEqual(cli.timeline_rerun_args(["h.c", "--slice-formula", "--unwind", "3"], failed),
                         ["h.c", "--unwind", "3", "--property", "main.assertion.3"])

    def test_no_rerun_without_slicing_or_failures(self):
        failed = [results.Property("main.assertion.3", "P5 Done", "FAILURE")]
        self.assertIsNone(cli.timeline_rerun_args(["h.c"], failed))
        self.assertIsNone(cli.timeline_rerun_args(["h.c", "--slice-formula"], []))
