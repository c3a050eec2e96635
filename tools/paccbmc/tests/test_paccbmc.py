"""paccbmc on CBMC output written out by hand: the verdict (properties hold, reachability checks reached,
known open failures) and the counterexample table."""
import json
import unittest

from paccbmc import cli, loops, results, timeline


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

    def test_a_split_run_selects_its_part(self):
        shown = json.dumps([{"program": "CBMC 6.6.0"}, {"properties": [
            {"name": "main.assertion.1", "description": "P5 Done"},
            {"name": "main.assertion.2", "description": "reach: Done"},
            {"name": "FB.array_bounds.3", "description": "array 'x' upper bound"}]}])
        self.assertEqual(results.selected(shown, reach=True), ["main.assertion.2"])
        self.assertEqual(results.selected(shown, reach=False), ["main.assertion.1", "FB.array_bounds.3"])

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

    def test_a_split_runs_properties_give_way_to_the_failed_ones(self):
        failed = [results.Property("main.assertion.3", "P5 Done", "FAILURE")]
        args = ["h.c", "--slice-formula", "--property", "main.assertion.3", "--property", "main.assertion.4"]
        self.assertEqual(cli.timeline_rerun_args(args, failed), ["h.c", "--property", "main.assertion.3"])

    def test_no_rerun_without_slicing_or_failures(self):
        failed = [results.Property("main.assertion.3", "P5 Done", "FAILURE")]
        self.assertIsNone(cli.timeline_rerun_args(["h.c"], failed))
        self.assertIsNone(cli.timeline_rerun_args(["h.c", "--slice-formula"], []))


class UnwindsetLoops(unittest.TestCase):
    """The loops an --unwindset bounds, checked against the text of their source lines (a stale number bounded
    another loop silently)."""

    def setUp(self):
        import tempfile
        from pathlib import Path
        self.dir = tempfile.TemporaryDirectory()
        self.source = Path(self.dir.name) / "FB.st"
        self.source.write_text("Scan := Scan + 1;\nFOR I := 0 TO 3 DO\nEND_FOR;\nWHILE Serving <> NextTicket DO\n")
        self.found = {"FB_body.0": {"file": str(self.source), "line": "2"},
                      "FB_body.1": {"file": "FB.st", "line": "4", "workingDirectory": self.dir.name},
                      "init$link2.0": {"file": str(self.source), "line": "2"}}

    def tearDown(self):
        self.dir.cleanup()

    def test_loops_of_every_unwindset(self):
        args = ["h.c", "--unwindset", "FB_body.1:3,init$link2.0:5", "--unwind", "4", "--unwindset", "main.0:19"]
        self.assertEqual(loops.unwindset_loops(args), ["FB_body.1", "init$link2.0", "main.0"])

    def test_the_loop_meant_passes(self):
        self.assertEqual(loops.check(["FB_body.1"], {"FB_body.1": "WHILE Serving"}, self.found), [])

    def test_a_moved_number_fails_naming_the_line_it_bounds_now(self):
        problems = loops.check(["FB_body.0"], {"FB_body.0": "WHILE Serving"}, self.found)
        self.assertEqual(len(problems), 1)
        self.assertIn("FOR I := 0 TO 3 DO", problems[0])
        self.assertIn("not the loop meant", problems[0])

    def test_a_loop_without_a_pattern_or_unknown_fails(self):
        self.assertIn("has no --loop", loops.check(["FB_body.1"], {}, self.found)[0])
        self.assertIn("no such loop", loops.check(["FB_body.7"], {"FB_body.7": "WHILE"}, self.found)[0])

    def test_one_pattern_covers_every_linked_copy(self):
        self.assertEqual(loops.check(["init$link2.0"], {"init.0": "FOR I"}, self.found), [])

    def test_show_loops_keeps_the_preprocessor_options(self):
        args = loops.show_loops_args(["-DK=6", "-I", "gen", "h.c", "a.c", "--unwind", "17"], ["a.c"])
        self.assertEqual(args, ["-DK=6", "-I", "gen", "a.c", "--show-loops", "--json-ui"])

    def test_a_unit_of_translated_files_gives_the_files_that_hold_the_loops(self):
        from pathlib import Path
        folder = Path(self.dir.name)
        (folder / "FB.c").write_text("void FB_body(void) { while (1) {} }\n")
        (folder / "F.c").write_text("int F(void) { return 0; }\n")
        (folder / "h.c").write_text("int main(void) { FB_body(); }\n")
        unit = folder / "fb_sources.c"
        unit.write_text(f'/* one unit */\n#include "{folder / "FB.c"}"\n#include "{folder / "F.c"}"\n')
        files = loops.sources_for(["FB_body.0"], [str(folder / "h.c"), str(unit), "--unwind", "3"])
        self.assertEqual(files, [str(folder / "h.c"), str(folder / "FB.c")])

    def test_a_pattern_must_name_its_loop(self):
        with self.assertRaises(loops.LoopError):
            loops.parse_patterns(["FB_body.1"])
