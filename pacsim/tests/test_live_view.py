"""pac-sim's live view and fault endpoint, and the library's FBs over Modbus (docs/virtual_commissioning.md).

The endpoints and faults come from the tables of the docs, the registers from its map, so the test checks the
program against what a user reads. Environment: PACSIM, PACSIM_PLC (the binaries), PAC_SOURCE_DIR.
  LiveViewTest    the docs' endpoints and faults are the program's; the state shows the modules of the map and a
                  Modbus client's command with its name; faults from the endpoint reach the Modbus client; bad
                  requests get 400 or 404
  BrowserTest     Debian's chromium through Selenium: the page shows an axis moving after a move arrives over
                  Modbus, and a fault injected with the page's button reaches the Modbus client
  ClosedLoopTest  pac-sim-plc: the demo scenario's steps over Modbus at a 10 ms PLC cycle end as in the process"""
import json
import os
import re
import shutil
import subprocess
import unittest
import urllib.error
import urllib.request

from test_pacsim import (AXIS_ABSOLUTE, AXIS_ACTIVE, AXIS_DRIVE_ENABLED, AXIS_ERROR, AXIS_ON, AXIS_START, BF,
                         CTRL_NO_REQUEST, CTRL_ONLINE_ACTIVE, CTRL_READY, CTRL_START_ONLINE, DOCS, EXAMPLES, LOOPBACK,
                         REPO, SEND, PacSim, docs_map, real_registers, registers_real, wait_for)

PACSIM_PLC = os.environ["PACSIM_PLC"]


def docs_table(marker):
    """The rows of the table after `<!-- marker -->` in the docs, as lists of cells."""
    with open(DOCS, encoding="utf-8") as f:
        lines = f.read().splitlines()
    start = lines.index(f"<!-- {marker} -->")
    rows = []
    for line in lines[start + 3:]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip("|").split("|")])
    return rows


class LiveViewTestCase(unittest.TestCase):
    """One pac-sim of the example with the live view for the class; a Modbus client for each test."""

    @classmethod
    def setUpClass(cls):
        cls.map = docs_map()
        cls.sim = PacSim(args=("--http", "0"))
        assert cls.sim.http_port, "pac-sim printed no live view"
        cls.base = f"http://{LOOPBACK}:{cls.sim.http_port}"

    @classmethod
    def tearDownClass(cls):
        code, out = cls.sim.stop()
        assert code == 0, (code, out)

    def setUp(self):
        self.modbus = self.sim.client()

    def tearDown(self):
        self.modbus.close()

    def http(self, method, path, body=None):
        """(status, decoded JSON or text) of one request."""
        data = None if body is None else (body if isinstance(body, bytes) else json.dumps(body).encode())
        request = urllib.request.Request(self.base + path, data=data, method=method)
        try:
            with urllib.request.urlopen(request, timeout=5) as response:
                status, text, kind = response.status, response.read().decode(), response.headers["Content-Type"]
        except urllib.error.HTTPError as e:
            status, text, kind = e.code, e.read().decode(), e.headers["Content-Type"]
        return status, json.loads(text) if (kind or "").startswith("application/json") else text

    def read_in(self, module, offset=0, count=1):
        response = self.modbus.read_input_registers(self.map[module][1] + offset, count=count, device_id=1)
        self.assertFalse(response.isError(), response)
        return response.registers

    def write_out(self, module, offset, values):
        response = self.modbus.write_registers(self.map[module][0] + offset, values, device_id=1)
        self.assertFalse(response.isError(), response)

    def online_with_axis_on(self):
        """ONLINE through the CTRL module, Axis ON on axis 1 (manual 2.5.1, 2.7.1), as test_pacsim does."""
        wait_for(lambda: self.read_in("CTRL")[0] & CTRL_READY, 5, "CTRL ready")
        self.write_out("CTRL", 0, [CTRL_NO_REQUEST | CTRL_START_ONLINE])
        wait_for(lambda: self.read_in("CTRL")[0] & CTRL_ONLINE_ACTIVE, 5, "ONLINE active")
        self.write_out("CTRL", 0, [CTRL_NO_REQUEST])
        self.write_out("AXIS 1", 0, [0, AXIS_ON, 1000, 1000] + real_registers(0.0))
        wait_for(lambda: self.read_in("AXIS 1", 1)[0] & AXIS_DRIVE_ENABLED, 5, "axis 1 DRIVE ENABLED")

    def start_move(self, target, speed):
        """An absolute move of axis 1 at `speed` per mille; Start falls once ACTIVE shows it taken over."""
        job = [0, AXIS_ON | AXIS_ABSOLUTE, 1000, speed] + real_registers(target)
        self.write_out("AXIS 1", 0, [0, job[1] | AXIS_START] + job[2:])
        wait_for(lambda: self.read_in("AXIS 1", 1)[0] & AXIS_ACTIVE, 5, "axis 1 ACTIVE")
        self.write_out("AXIS 1", 0, job)

    def read_r1(self):
        """Reads R1 with 1907 on the CMD module (manual 2.4, 5.2.4) until RF = SEND and BF."""
        wait_for(lambda: self.read_in("CTRL")[0] & CTRL_READY, 5, "CTRL ready")
        send_flag = (self.read_in("CMD", 3)[0] & SEND) ^ SEND
        self.write_out("CMD", 0, [0, 0, 1, send_flag | 0x1907])
        wait_for(lambda: (lambda r: (r[3] & SEND) == send_flag and r[3] & BF)(self.read_in("CMD", count=4)), 5,
                 "1907 acknowledged")

    def answered_r1(self):
        """The state once the live view shows the last handshake, 1907, answered."""
        def answered():
            state = self.http("GET", "/api/state")[1]["controllers"][0]
            last = state["handshakes"][-1] if state["handshakes"] else {}
            return state if last.get("code") == "16#1907" and last["answered"] else None
        return wait_for(answered, 5, "the live view shows 1907 answered")

    def axis_error_over_modbus(self):
        """The axis error number of axis 1 once its status word shows the axis error (2.7.2), else 0."""
        module = self.read_in("AXIS 1", count=4)
        return module[3] if module[1] & AXIS_ERROR else 0


class LiveViewTest(LiveViewTestCase):
    def test_the_docs_endpoints_and_faults_are_the_programs(self):
        endpoints = docs_table("live view endpoints")
        endpoints = [(method, path.strip("`"), what) for method, path, what in endpoints]
        self.assertEqual([(m, p) for m, p, _ in endpoints],
                         [("GET", "/"), ("GET", "/api/state"), ("GET", "/api/faults"), ("POST", "/api/fault")])
        for method, path, _ in endpoints:
            status, _ = self.http(method, path, {"fault": "link_restore"} if method == "POST" else None)
            self.assertEqual(status, 200, f"{method} {path}")
        status, faults = self.http("GET", "/api/faults")
        self.assertEqual(faults["faults"], [row[0].strip("`") for row in docs_table("live view faults")])
        # Every key the docs name for /api/state is there, and no other.
        self.read_r1()
        state = self.answered_r1()
        self.assertIn('{"controllers": [...]}', endpoints[1][2])
        keys = {*state, *state["axes"][0], *state["handshakes"][-1], *state["modules"][0],
                *state["modules"][0]["to_pac"]}
        self.assertEqual(set(re.findall(r"`(\w+)`", endpoints[1][2])), keys)
        self.assertEqual(self.http("GET", "/api/nothing")[0], 404)

    def test_the_state_shows_the_map_and_a_command_with_its_name(self):
        self.read_r1()
        state = self.answered_r1()
        last = state["handshakes"][-1]
        self.assertEqual(last["parameter"], 1)
        self.assertAlmostEqual(registers_real([last["ack_data"] >> 16, last["ack_data"] & 0xFFFF]), 640.0)
        self.assertNotEqual(last["meaning"], "unknown command")
        self.assertEqual([m["name"] for m in state["modules"]], list(self.map)[:4])  # CMD, CTRL, 2 axes
        cmd = state["modules"][0]
        self.assertEqual(len(cmd["to_pac"]["hex"].split()), 8)
        self.assertIn("command", dict(cmd["to_pac"]["fields"]))
        self.assertIn("operating status", dict(cmd["from_pac"]["fields"]))

    def test_faults_from_the_endpoint_reach_the_modbus_client(self):
        self.online_with_axis_on()
        status, answer = self.http("POST", "/api/fault", {"fault": "axis_error", "axis": 1, "number": 70})
        self.assertEqual(status, 200, answer)
        self.assertEqual(wait_for(self.axis_error_over_modbus, 5, "axis error over Modbus"), 70)

        status, answer = self.http("POST", "/api/fault", {"fault": "link_loss"})
        self.assertEqual(status, 200, answer)
        wait_for(lambda: self.read_in("CMD", count=4) == [0, 0, 0, 0], 5, "zeros while the link is lost")
        self.assertEqual(self.http("POST", "/api/fault", {"fault": "link_restore"})[0], 200)

        status, answer = self.http("POST", "/api/fault", {"fault": "power_cycle"})
        self.assertEqual(status, 200, answer)
        wait_for(lambda: self.read_in("CTRL")[0] & CTRL_READY, 5, "ready again after the power cycle")

    def test_bad_requests(self):
        status, answer = self.http("POST", "/api/fault", {"fault": "meltdown"})
        self.assertEqual(status, 400)
        self.assertIn("link_loss", answer["error"])
        self.assertEqual(self.http("POST", "/api/fault", {"fault": "axis_error", "axis": 9})[0], 400)
        self.assertEqual(self.http("POST", "/api/fault", {"fault": "restart", "controller": "pac9"})[0], 404)
        self.assertEqual(self.http("POST", "/api/fault", b"{not json")[0], 400)
        self.assertEqual(self.http("POST", "/api/fault", {"fault": 3})[0], 400)
        self.assertEqual(self.http("GET", "/api/state")[0], 200)


class BrowserTest(LiveViewTestCase):
    def test_the_page_shows_an_axis_moving_and_its_button_injects_a_fault(self):
        self.assertTrue(shutil.which("chromedriver") and shutil.which("chromium"),
                        "Debian's chromium and chromium-driver are needed (./run test installs them)")
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
        from selenium.webdriver.common.by import By
        from selenium.webdriver.support.ui import Select, WebDriverWait

        options = webdriver.ChromeOptions()
        options.binary_location = shutil.which("chromium")
        for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"):
            options.add_argument(argument)
        browser = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
        try:
            browser.get(self.base + "/")
            wait = WebDriverWait(browser, 10, poll_frequency=0.02)
            # Read through JavaScript: the page rebuilds its tables with every update.
            text = lambda element_id: browser.execute_script(
                "const e = document.getElementById(arguments[0]); return e ? e.textContent : null;", element_id)
            position = lambda: float(text("position-pac1-1"))
            wait.until(lambda b: text("position-pac1-1") is not None)
            updates = int(text("updates"))

            self.online_with_axis_on()
            start = position()
            self.start_move(start + 100.0, 100)  # a tenth of the speed: seconds on the way, on a loaded machine too
            # The page shows the axis on its way: a position between start and target, then another one.
            seen = wait.until(lambda b: (lambda p: p if start + 1.0 < p < start + 99.0 else None)(position()))
            wait.until(lambda b: position() > seen)
            self.assertGreater(int(text("updates")), updates)

            # The page's limit switch button for axis 1: the Modbus client reads axis error 64 (16#40).
            Select(browser.find_element(By.ID, "fault-controller")).select_by_visible_text("pac1")
            browser.find_element(By.ID, "fault-limit_switch").click()
            wait.until(lambda b: "limit_switch injected into pac1" in text("fault-result"))
            self.assertEqual(wait_for(self.axis_error_over_modbus, 5, "axis error over Modbus"), 64)
            wait.until(lambda b: text("axis-error-pac1-1") == "64")
        finally:
            browser.quit()


class ClosedLoopTest(unittest.TestCase):
    def test_the_demo_over_modbus_ends_as_in_the_process(self):
        sim = PacSim(os.path.join(EXAMPLES, "demo_controller.json"), args=("--http", "0"))
        try:
            run = subprocess.run([PACSIM_PLC, "--port", str(sim.port()), "--http", str(sim.http_port),
                                  "--plc-cycle-ms", "10", "--compare", os.path.join(REPO, "scenario", "demo.json")],
                                 capture_output=True, text=True, timeout=120)
        finally:
            sim.stop()
        print(run.stdout)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn("every step passed, every step ended as in the process", run.stdout)


if __name__ == "__main__":
    unittest.main()
