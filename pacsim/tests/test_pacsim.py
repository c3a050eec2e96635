"""pac-sim against a Modbus TCP client that shares no code with it (pymodbus), on loopback only.

The register numbers come from the register map of docs/virtual_commissioning.md (read from the page), the bits
and fields from the manual's sections the page cites, so the test checks the program against what a PLC
programmer reads. Environment: PACSIM (the pac-sim binary), PAC_SOURCE_DIR (the repository).
  CommissioningTest   the example configuration: a command on the CMD module, ONLINE through the CTRL module,
                      an axis switched on and moved through its axis module, its position read three ways
  RobustnessTest      exceptions for bad function codes, addresses, quantities and unit ids, the connection
                      still served after each; a client gone or stalled mid-frame, two clients writing at once,
                      seeded random bytes (the seed is printed), clients beyond the limit: nothing lost, the
                      server answers throughout
  SerialTest          RS232 over TCP: the manual's 3.4.2 frames byte for byte, a frame sent a byte at a time,
                      one client at a time
  PseudoTerminalTest  RS232 on a pseudo-terminal: a frame of 3.4.2
  CommandLineTest     --help, --version, refusals with the JSONPath, SIGINT and SIGTERM stop it cleanly
  DocsAndSchemaTest   the docs' map table is pac-sim --print-map's; every configuration file of pacsim/examples
                      is valid under pacsim/pacsim.schema.json and passes --check; damaged, both refuse it"""
import json
import os
import random
import re
import select
import signal
import socket
import struct
import subprocess
import threading
import time
import unittest

import jsonschema
import referencing
from pymodbus.client import ModbusTcpClient

PACSIM = os.environ["PACSIM"]
REPO = os.environ["PAC_SOURCE_DIR"]
DOCS = os.path.join(REPO, "docs", "virtual_commissioning.md")
EXAMPLES = os.path.join(REPO, "pacsim", "examples")
TWO_AXES = os.path.join(EXAMPLES, "two_axes.json")
LOOPBACK = "127.0.0.1"

# Manual 2.5.1 / 2.5.2: the CTRL control word (bits 0..2 low active) and status word.
CTRL_NO_REQUEST = 0x0007
CTRL_START_ONLINE = 0x0010
CTRL_READY = 1 << 0
CTRL_ONLINE_ACTIVE = 1 << 10
# Manual 2.7.1 / 2.7.2: the axis module's control and status word (low 16 bits).
AXIS_ON = 1 << 0
AXIS_START = 1 << 2
AXIS_ABSOLUTE = 1 << 6
AXIS_DRIVE_ENABLED = 1 << 0
AXIS_ACTIVE = 1 << 7
AXIS_REFERENCED = 1 << 8
AXIS_CMD_ERROR = 1 << 14
AXIS_ERROR = 1 << 15
# Manual 2.4: SEND / RF flag, BF; 2.4.2 operating status 31 = ONLINE.
SEND = 1 << 15
BF = 1 << 13
STATUS_ONLINE = 31


def docs_map():
    """{module: (to-PAC holding, from-PAC input, from-PAC holding first register, registers)} from the page's table."""
    with open(DOCS, encoding="utf-8") as f:
        lines = f.read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("<!-- pac-sim --print-map"))
    table = {}
    for line in lines[start + 3:]:
        if not line.startswith("|"):
            break
        cells = [cell.strip() for cell in line.strip("|").split("|")]
        ranges = [tuple(int(n) for n in cell.split("..")) for cell in cells[2:]]
        table[cells[0]] = (ranges[0][0], ranges[1][0], ranges[2][0], ranges[0][1] - ranges[0][0] + 1)
    return table


def real_registers(value):
    high, low = struct.unpack(">HH", struct.pack(">f", value))
    return [high, low]


def registers_real(registers):
    return struct.unpack(">f", struct.pack(">HH", *registers))[0]


def wait_for(predicate, seconds, what):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = predicate()
        if value:
            return value
        time.sleep(0.01)
    raise AssertionError(f"not within {seconds} s: {what}")


class PacSim:
    """pac-sim on a free loopback port: the controllers it prints ({name: (port, unit id)}), their RS232 ports
    ({name: port}) and the live view's port (with --http), stopped by a signal."""

    def __init__(self, config=TWO_AXES, args=()):
        self.process = subprocess.Popen([PACSIM, "--port", "0", "--address", LOOPBACK, *args, config],
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.controllers, self.serial_ports, self.http_port = {}, {}, None
        for line in self.process.stdout:
            view = re.match(r"pac-sim: live view http://127\.0\.0\.1:(\d+)/", line)
            if view:
                self.http_port = int(view.group(1))
            serial = re.match(r"(\S+): RS232 \(COM1\) (?:raw TCP 127\.0\.0\.1:(\d+)|pseudo-terminal (\S+)), ", line)
            if serial:
                self.serial_ports[serial.group(1)] = int(serial.group(2)) if serial.group(2) else serial.group(3)
            found = re.match(r"(\S+): Modbus TCP 127\.0\.0\.1:(\d+) unit id (\d+): ", line)
            if found:
                self.controllers[found.group(1)] = (int(found.group(2)), int(found.group(3)))
            if line.startswith("pac-sim: running"):
                break
        if not self.controllers:
            self.process.kill()
            raise AssertionError("pac-sim did not start: " + self.process.stderr.read())

    def port(self, name="pac1"):
        return self.controllers[name][0]

    def client(self, name="pac1"):
        client = ModbusTcpClient(LOOPBACK, port=self.port(name), timeout=3, retries=0)
        assert client.connect(), "cannot connect to pac-sim"
        return client

    def stop(self, sig=signal.SIGINT):
        """Stops it with `sig`; its exit code and the rest of its standard output."""
        self.process.send_signal(sig)
        out, err = self.process.communicate(timeout=10)
        assert err == "", err
        return self.process.returncode, out

    def alive(self):
        return self.process.poll() is None


class ModbusTestCase(unittest.TestCase):
    """One pac-sim of the example for the class; the map of the docs."""

    @classmethod
    def setUpClass(cls):
        cls.map = docs_map()
        cls.sim = PacSim()

    @classmethod
    def tearDownClass(cls):
        code, out = cls.sim.stop()
        assert code == 0 and "pac-sim: stopped by a signal" in out, (code, out)

    def setUp(self):
        self.modbus = self.sim.client()

    def tearDown(self):
        self.modbus.close()

    def first(self, module):
        return self.map[module][0]

    def read_in(self, module, offset=0, count=1, client=None):
        response = (client or self.modbus).read_input_registers(self.map[module][1] + offset, count=count, device_id=1)
        self.assertFalse(response.isError(), response)
        return response.registers

    def write_out(self, module, offset, values, client=None):
        response = (client or self.modbus).write_registers(self.map[module][0] + offset, values, device_id=1)
        self.assertFalse(response.isError(), response)

    def assert_exception(self, response, code):
        self.assertTrue(response.isError(), f"expected exception {code}, got {response}")
        self.assertEqual(response.exception_code, code, response)

    def assert_still_served(self, client=None):
        """The connection (and the server) answer a correct request after whatever came before."""
        self.assertEqual(len(self.read_in("CMD", count=4, client=client)), 4)


class CommissioningTest(ModbusTestCase):
    def test_a_command_online_and_an_axis_moved(self):
        # The boot: the CTRL status word shows the controller ready once the all-zero replies end.
        wait_for(lambda: self.read_in("CTRL")[0] & CTRL_READY, 5, "CTRL status word: ready")

        # CMD (manual 2.4, 5.2.4): read R1 with 1907, SEND toggled; the acknowledgement is 640.0.
        send_flag = (self.read_in("CMD", 3)[0] & SEND) ^ SEND
        self.write_out("CMD", 0, [0, 0, 1, send_flag | 0x1907])
        reply = wait_for(lambda: (lambda r: r if (r[3] & SEND) == send_flag and r[3] & BF else None)(
            self.read_in("CMD", count=4)), 5, "RF = SEND and BF for 1907")
        self.assertEqual(reply[3] & 0x5FFF, 0, f"no command error: {reply[3]:#06x}")
        self.assertAlmostEqual(registers_real(reply[0:2]), 640.0)

        # CTRL (2.5.1): Start ONLINE until the status word shows ONLINE active, then no request.
        self.write_out("CTRL", 0, [CTRL_NO_REQUEST | CTRL_START_ONLINE])
        wait_for(lambda: self.read_in("CTRL")[0] & CTRL_ONLINE_ACTIVE, 5, "ONLINE active")
        self.write_out("CTRL", 0, [CTRL_NO_REQUEST])
        self.assertEqual(self.read_in("CMD", 2)[0] & 0xFF, STATUS_ONLINE)

        # Axis module 1 (2.7.1): Axis ON until DRIVE ENABLED; the axis is referenced at power-on.
        self.write_out("AXIS 1", 0, [0, AXIS_ON, 1000, 1000] + real_registers(0.0))
        status = wait_for(lambda: (lambda s: s if s & AXIS_DRIVE_ENABLED else 0)(self.read_in("AXIS 1", 1)[0]),
                          5, "axis 1 DRIVE ENABLED")
        self.assertTrue(status & AXIS_REFERENCED)

        # Absolute move to 50.0 at half speed: the whole module in one request, Start with the job; once ACTIVE
        # shows the job taken over (2.7.3.2), Start back to 0; ACTIVE falls when the job is complete.
        job = [0, AXIS_ON | AXIS_ABSOLUTE, 1000, 500] + real_registers(50.0)
        self.write_out("AXIS 1", 0, [0, job[1] | AXIS_START] + job[2:])
        wait_for(lambda: self.read_in("AXIS 1", 1)[0] & AXIS_ACTIVE, 5, "axis 1 ACTIVE (job taken over)")
        self.write_out("AXIS 1", 0, job)
        seen = []

        def ended():
            module = self.read_in("AXIS 1", count=6)
            seen.append(registers_real(module[4:6]))
            return module if not module[1] & AXIS_ACTIVE else None

        module = wait_for(ended, 30, "axis 1 at its target (ACTIVE 0)")
        self.assertFalse(module[1] & (AXIS_CMD_ERROR | AXIS_ERROR), f"status {module[1]:#06x}, errors {module[2:4]}")
        self.assertAlmostEqual(registers_real(module[4:6]), 50.0, places=3)
        self.assertEqual(seen[-1], registers_real(module[4:6]))

        # The same position as holding registers from 1024 on, and through function code 23.
        holding = self.modbus.read_holding_registers(self.map["AXIS 1"][2] + 4, count=2, device_id=1)
        self.assertAlmostEqual(registers_real(holding.registers), 50.0, places=3)
        both = self.modbus.readwrite_registers(read_address=self.map["AXIS 1"][2] + 4, read_count=2,
                                               write_address=self.first("AXIS 1") + 2, values=[1000, 1000],
                                               device_id=1)
        self.assertFalse(both.isError(), both)
        self.assertAlmostEqual(registers_real(both.registers), 50.0, places=3)
        written = self.modbus.read_holding_registers(self.first("AXIS 1"), count=6, device_id=1).registers
        self.assertEqual(written, [0, AXIS_ON | AXIS_ABSOLUTE, 1000, 1000] + real_registers(50.0))


class RobustnessTest(ModbusTestCase):
    def registers(self):
        """The registers of each direction of the example (CMD, CTRL, two axis modules): 20."""
        return self.map["AXIS 2"][0] + self.map["AXIS 2"][3]

    def test_function_codes_not_served_get_exception_1(self):
        self.assert_exception(self.modbus.read_coils(0, count=1, device_id=1), 1)
        self.assert_exception(self.modbus.read_discrete_inputs(0, count=1, device_id=1), 1)
        self.assert_exception(self.modbus.write_coil(0, True, device_id=1), 1)
        self.assert_exception(self.modbus.mask_write_register(address=0, and_mask=0, or_mask=0, device_id=1), 1)
        # Encapsulated interface (43): a frame libmodbus reads only to its function code; the rest is dropped.
        self.assert_exception(self.modbus.read_device_information(device_id=1), 1)
        self.assert_still_served()
        # 128..255 are exception responses, never requests: not Modbus, the connection ends without an answer.
        for function in (0x80, 0x83, 0xFF):
            with socket.create_connection((LOOPBACK, self.sim.port())) as raw:
                raw.settimeout(3)
                raw.sendall(self.raw_frame(1, function, struct.pack(">HH", 0, 1)))
                try:
                    answer = raw.recv(16)
                except ConnectionResetError:  # closed with the rest of the frame unread: a reset, not a FIN
                    answer = b""
                self.assertEqual(answer, b"", f"function code {function:#04x}")
        self.assert_still_served()

    def test_registers_outside_the_map_get_exception_2(self):
        end = self.registers()  # the first register after the last module (20 for the example)
        base = self.map["CMD"][2]  # from PAC as holding registers
        self.assert_exception(self.modbus.read_input_registers(end, count=1, device_id=1), 2)
        self.assert_exception(self.modbus.read_input_registers(end - 2, count=3, device_id=1), 2)
        self.assert_exception(self.modbus.read_holding_registers(end, count=1, device_id=1), 2)
        self.assert_exception(self.modbus.read_holding_registers(base - 1, count=2, device_id=1), 2)
        self.assert_exception(self.modbus.read_holding_registers(base + end - 1, count=2, device_id=1), 2)
        self.assert_exception(self.modbus.read_input_registers(base, count=1, device_id=1), 2)
        self.assert_exception(self.modbus.write_register(end, 1, device_id=1), 2)
        self.assert_exception(self.modbus.write_registers(end - 1, [1, 2], device_id=1), 2)
        # From PAC is read only.
        self.assert_exception(self.modbus.write_register(base, 1, device_id=1), 2)
        self.assert_exception(self.modbus.readwrite_registers(read_address=0, read_count=1, write_address=base,
                                                              values=[1], device_id=1), 2)
        self.assert_exception(self.modbus.readwrite_registers(read_address=end, read_count=1, write_address=0,
                                                              values=[0], device_id=1), 2)
        self.assert_still_served()

    def test_quantities_out_of_range_get_exception_3(self):
        # pymodbus builds no such request: raw frames, answered with the function code + 0x80 and exception 3.
        frames = [(4, struct.pack(">HH", 0, 126)), (3, struct.pack(">HH", 0, 0)),
                  (16, struct.pack(">HHB", 0, 1, 4) + bytes(4)),  # byte count 4 for one register
                  (23, struct.pack(">HHHHB", 0, 126, 0, 1, 2) + bytes(2))]
        with socket.create_connection((LOOPBACK, self.sim.port())) as raw:
            raw.settimeout(3)
            for transaction, (function, payload) in enumerate(frames):
                raw.sendall(self.raw_frame(transaction, function, payload))
                self.assertEqual(raw.recv(64), self.raw_frame(transaction, function | 0x80, bytes([3])), function)
        self.assert_still_served()

    def test_unit_ids(self):
        self.assert_exception(self.modbus.read_input_registers(0, count=4, device_id=7), 0x0A)
        # One controller on the port: 0 and 255 reach it too.
        for unit in (0, 255):
            response = self.modbus.read_input_registers(0, count=4, device_id=unit)
            self.assertFalse(response.isError(), f"unit {unit}: {response}")
        self.assert_still_served()

    def raw_frame(self, transaction, function, payload, unit=1):
        pdu = bytes([function]) + payload
        return struct.pack(">HHHB", transaction, 0, len(pdu) + 1, unit) + pdu

    def test_a_client_gone_or_stalled_mid_frame_loses_nothing(self):
        axis2 = self.first("AXIS 2")
        self.write_out("AXIS 2", 2, [111])
        frame = self.raw_frame(1, 16, struct.pack(">HHB", axis2 + 2, 1, 2) + struct.pack(">H", 999))
        for cut in range(1, len(frame)):
            with socket.create_connection((LOOPBACK, self.sim.port())) as raw:
                raw.sendall(frame[:cut])
            self.assertEqual(self.modbus.read_holding_registers(axis2 + 2, count=1, device_id=1).registers, [111],
                             f"a frame cut after {cut} bytes wrote nothing")
        # A client stalled in the middle of a frame holds up no other client, and is dropped after 0.5 s.
        with socket.create_connection((LOOPBACK, self.sim.port())) as stalled:
            stalled.sendall(frame[:9])
            started = time.monotonic()
            self.assert_still_served()
            self.assertLess(time.monotonic() - started, 0.4, "another client waited for the stalled one")
            stalled.settimeout(3)
            self.assertEqual(stalled.recv(16), b"", "the stalled client is disconnected")
        self.assertEqual(self.modbus.read_holding_registers(axis2 + 2, count=1, device_id=1).registers, [111])
        # The whole frame on a raw socket: written, answered with the echo of 16.
        with socket.create_connection((LOOPBACK, self.sim.port())) as raw:
            raw.sendall(frame)
            raw.settimeout(3)
            self.assertEqual(raw.recv(64), self.raw_frame(1, 16, struct.pack(">HH", axis2 + 2, 1)))
        self.assertEqual(self.modbus.read_holding_registers(axis2 + 2, count=1, device_id=1).registers, [999])

    def test_two_clients_at_once_lose_nothing(self):
        second = self.sim.client()
        failures = []

        def writer(client, register, values):
            for value in values:
                response = client.write_register(register, value, device_id=1)
                back = client.read_holding_registers(register, count=1, device_id=1)
                if response.isError() or back.isError() or back.registers != [value]:
                    failures.append((register, value, response, back))

        # Two registers of one module (axis 2's acceleration and speed), each client its own, 300 writes each.
        first = self.first("AXIS 2")
        threads = [threading.Thread(target=writer, args=(self.modbus, first + 2, range(1, 301))),
                   threading.Thread(target=writer, args=(second, first + 3, range(1001, 1301)))]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        second.close()
        self.assertEqual(failures, [])
        self.assertEqual(self.modbus.read_holding_registers(first + 2, count=2, device_id=1).registers, [300, 1300])

    def test_clients_beyond_the_limit_are_closed_and_room_comes_back(self):
        read = self.raw_frame(9, 4, struct.pack(">HH", 0, 4))
        held = []
        try:
            def connect_served():
                raw = socket.create_connection((LOOPBACK, self.sim.port()))
                raw.settimeout(3)
                try:
                    raw.sendall(read)
                    if raw.recv(64)[7:8] == b"\x04":
                        return raw
                except OSError:
                    pass
                raw.close()  # refused: a client of an earlier test the server has not seen leave yet
                return None

            for _ in range(31):  # with this test's own client: 32, the limit (docs: "at most 32 clients at once")
                held.append(wait_for(connect_served, 5, "a client served below the limit"))
            with socket.create_connection((LOOPBACK, self.sim.port())) as extra:
                extra.settimeout(3)
                self.assertEqual(extra.recv(16), b"", "the 33rd client is closed at once")
            self.assert_still_served()
        finally:
            for raw in held:
                raw.close()

        def served():
            try:
                with socket.create_connection((LOOPBACK, self.sim.port())) as again:
                    again.settimeout(1)
                    again.sendall(read)
                    return again.recv(64)[7:8] == b"\x04"
            except (OSError, IndexError):
                return False

        wait_for(served, 5, "a new client served once the others have gone")

    def test_random_bytes(self):
        seed = int(os.environ.get("PACSIM_SEED", random.SystemRandom().randrange(1 << 32)))
        print(f"random bytes: seed {seed} (PACSIM_SEED={seed} repeats it)")
        rng = random.Random(seed)
        # The to-PAC image before: random frames may write it (that is what a frame does), so it is put back.
        before = self.modbus.read_holding_registers(0, count=self.registers(), device_id=1).registers
        for _ in range(200):
            with socket.create_connection((LOOPBACK, self.sim.port())) as raw:
                raw.settimeout(0.05)
                kind = rng.randrange(3)
                if kind == 0:  # noise
                    data = bytes(rng.randrange(256) for _ in range(rng.randrange(1, 300)))
                else:  # a well-formed MBAP with a random PDU: function codes, addresses, quantities, unit ids
                    payload = bytes(rng.randrange(256) for _ in range(rng.randrange(0, 20)))
                    function = rng.choice([3, 4, 6, 16, 23, rng.randrange(256)])
                    data = self.raw_frame(rng.randrange(1 << 16), function, payload,
                                          unit=rng.choice([1, 0, 255, rng.randrange(256)]))
                raw.sendall(data)
                try:
                    raw.recv(512)
                except (socket.timeout, ConnectionResetError):
                    pass
        self.assertTrue(self.sim.alive())
        self.modbus.write_registers(0, before, device_id=1)
        self.assert_still_served()


def frame(text):
    """Manual 3.1: SOH STX text ETX CHECK EOT, CHECK the XOR of the text in decimal (the master frames' rule)."""
    check = 0
    for c in text.encode("ascii"):
        check ^= c
    return b"\x01\x02" + text.encode("ascii") + b"\x03" + str(check).encode("ascii") + b"\x04"


class SerialTest(unittest.TestCase):
    """The example with COM1 on a TCP port of its own (any free one)."""

    @classmethod
    def setUpClass(cls):
        with open(TWO_AXES, encoding="utf-8") as f:
            config = json.load(f)
        config["controllers"][0]["rs232"] = {"port": 0, "baud": 9600}
        config["controllers"][0]["controller"]["inputs"]["5"] = True  # the setup of manual 3.4.2
        cls.config = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"pacsim-serial-{os.getpid()}.json")
        with open(cls.config, "w", encoding="utf-8") as f:
            json.dump(config, f)
        cls.sim = PacSim(cls.config)
        time.sleep(0.1)  # the boot: 50 ms without an answer

    @classmethod
    def tearDownClass(cls):
        code, out = cls.sim.stop()
        os.remove(cls.config)
        assert code == 0, out

    def connect(self):
        line = socket.create_connection((LOOPBACK, self.sim.serial_ports["pac1"]))
        line.settimeout(3)
        return line

    def read_reply(self, line):
        reply = b""
        while not reply.endswith(b"\x04"):
            chunk = line.recv(64)
            self.assertTrue(chunk, f"the line closed after {reply!r}")
            reply += chunk
        return reply

    def test_the_manuals_frames(self):
        with self.connect() as line:
            # 3.4.2: 1900 (status) and 1907 R1 = 640.0 as the manual prints the replies (docs/manual_errata.md:
            # the reply's CHECK is the XOR with ETX).
            line.sendall(frame("1900;5;0;0"))
            self.assertEqual(self.read_reply(line), bytes.fromhex("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 03 35 37 04"))
            started = time.monotonic()
            request = frame("1907;1;1;0")
            for byte in request:  # a byte at a time, as a terminal program sends
                line.sendall(bytes([byte]))
                time.sleep(0.002)
            self.assertEqual(self.read_reply(line), bytes.fromhex(
                "01 02 30 3B 31 3B 31 3B 30 3B 31 3B 36 34 30 2E 30 30 30 30 03 32 31 04"))
            # 9600 baud, 10 bits a character: the request and the reply take their time on the line.
            self.assertGreater(time.monotonic() - started, (len(request) + 24) * 10 / 9600)

    def test_one_client_at_a_time(self):
        with self.connect() as line, self.connect() as second:
            self.assertEqual(second.recv(16), b"", "a second client is closed at once")
            line.sendall(frame("1900;5;0;0"))
            self.assertTrue(self.read_reply(line).startswith(b"\x01\x02"))


class PseudoTerminalTest(unittest.TestCase):
    """The example with COM1 on a pseudo-terminal, opened as a serial port is (raw mode is pac-sim's doing)."""

    def test_the_manuals_frame_on_a_pseudo_terminal(self):
        with open(TWO_AXES, encoding="utf-8") as f:
            config = json.load(f)
        config["controllers"][0]["rs232"] = {"pty": True}
        path = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"pacsim-pty-{os.getpid()}.json")
        with open(path, "w", encoding="utf-8") as f:
            json.dump(config, f)
        sim = PacSim(path)
        try:
            terminal = os.open(sim.serial_ports["pac1"], os.O_RDWR | os.O_NOCTTY)
            time.sleep(0.1)  # the boot
            os.write(terminal, frame("1907;1;1;0"))
            reply = b""
            end = time.monotonic() + 5
            while not reply.endswith(b"\x04") and time.monotonic() < end:
                if select.select([terminal], [], [], 0.1)[0]:
                    reply += os.read(terminal, 64)
            os.close(terminal)
            self.assertEqual(reply, bytes.fromhex("01 02 30 3B 31 3B 31 3B 30 3B 31 3B 36 34 30 2E 30 30 30 30 03 32 31 04"))
        finally:
            os.remove(path)
            self.assertEqual(sim.stop()[0], 0)


class CommandLineTest(unittest.TestCase):
    def run_pacsim(self, *args):
        return subprocess.run([PACSIM, *args], capture_output=True, text=True, timeout=30)

    def test_help_and_version(self):
        run = self.run_pacsim("--help")
        self.assertEqual(run.returncode, 0)
        self.assertIn("usage: pac-sim", run.stdout)
        with open(os.path.join(REPO, "st", "library.json"), encoding="utf-8") as f:
            version = json.load(f)["version"]
        run = self.run_pacsim("--version")
        self.assertEqual((run.returncode, run.stdout.split()[-1]), (0, version))

    def test_refusals_name_the_place(self):
        cases = [
            ({"controllers": [{"controller": {"inputsx": {}}}]}, '$.controllers[0].controller.inputsx: unknown key "inputsx"'),
            ({"controllers": [{"modules": {"axes": 9, "ctrl": True}}]}, "$.controllers[0].modules.axes: out of range"),
            ({"controllers": [{}, {"unit_id": 1}]}, "$.controllers[1]: contradiction"),
            ({"controllers": [{"controller": {"system_parameters": {"9999": 1}}}]},
             '$.controllers[0].controller.system_parameters["9999"]'),
            ({"controllers": []}, "$.controllers: out of range"),
            ({"port": 70000, "controllers": [{}]}, "$.port: out of range"),
        ]
        work = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"pacsim-refusals-{os.getpid()}.json")
        try:
            for document, message in cases:
                with open(work, "w", encoding="utf-8") as f:
                    json.dump(document, f)
                run = self.run_pacsim("--check", work)
                self.assertEqual(run.returncode, 2, document)
                self.assertIn(message, run.stderr, document)
        finally:
            os.remove(work)
        for args in (["--port", "x", TWO_AXES], ["--port", "65536", TWO_AXES], ["--seconds", "0", TWO_AXES],
                     ["--address", "localhost", TWO_AXES], ["--bogus", TWO_AXES], [], ["a.json", "b.json"]):
            self.assertEqual(self.run_pacsim(*args).returncode, 2, args)

    def test_a_signal_stops_it_cleanly(self):
        for sig in (signal.SIGINT, signal.SIGTERM):
            sim = PacSim()
            client = sim.client()  # a client connected when the signal comes
            self.assertFalse(client.read_input_registers(0, count=4, device_id=1).isError())
            code, out = sim.stop(sig)
            client.close()
            self.assertEqual(code, 0, out)
            self.assertRegex(out, r"pac-sim: stopped by a signal after \d+ ms: 1 connections")

    def test_seconds_and_stats(self):
        started = time.monotonic()
        run = self.run_pacsim("--port", "0", "--seconds", "0.5", "--stats", TWO_AXES)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertGreaterEqual(time.monotonic() - started, 0.5)
        self.assertIn("pac-sim: stopped after", run.stdout)
        # 5 ms controller cycles for 0.5 s: about 100 cycles, a late one counted with those it caught up; the last
        # look at the clock may run one or two past 0.5 s.
        found = re.search(r"pac-sim: cycles (\d+), lateness p50 \d+ us, p99 \d+ us, max \d+ us; CPU \d+ % of one core",
                          run.stdout)
        self.assertTrue(found, run.stdout)
        self.assertTrue(10 <= int(found.group(1)) <= 103, found.group(0))

    def test_a_port_in_use_is_refused(self):
        with socket.socket() as taken:
            taken.bind((LOOPBACK, 0))
            taken.listen()
            run = self.run_pacsim("--port", str(taken.getsockname()[1]), TWO_AXES)
        self.assertEqual(run.returncode, 3)
        self.assertIn("cannot listen on 127.0.0.1:", run.stderr)

    def test_two_controllers_on_one_port_by_unit_id(self):
        sim = PacSim(os.path.join(EXAMPLES, "eight_axes.json"))
        try:
            self.assertEqual(sim.port("cmd_only"), sim.port("eight_axes"))
            client = sim.client("eight_axes")
            self.assertFalse(client.read_input_registers(0, count=56, device_id=2).isError())
            self.assertEqual(client.read_input_registers(4, count=1, device_id=1).exception_code, 2)
            self.assertEqual(client.read_input_registers(0, count=1, device_id=255).exception_code, 0x0A)
            client.close()
        finally:
            self.assertEqual(sim.stop()[0], 0)


class DocsAndSchemaTest(unittest.TestCase):
    def test_the_docs_map_is_the_programs(self):
        with open(DOCS, encoding="utf-8") as f:
            lines = f.read().splitlines()
        start = next(i for i, line in enumerate(lines) if line.startswith("<!-- pac-sim --print-map"))
        command, controller = re.match(r"<!-- pac-sim --print-map (\S+): (\S+) -->", lines[start]).groups()
        documented = []
        for line in lines[start + 1:]:
            if not line.startswith("|"):
                break
            documented.append(line)
        run = subprocess.run([PACSIM, "--print-map", os.path.join(REPO, command)], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        sections = run.stdout.split("\n\n")
        index = next(i for i, s in enumerate(sections) if s.startswith(controller + " ("))
        self.assertEqual(documented, sections[index + 1].splitlines())

    def validator(self):
        def load(path):
            with open(path, encoding="utf-8") as f:
                return json.load(f)
        schema_path = os.path.join(REPO, "pacsim", "pacsim.schema.json")
        scenario_path = os.path.join(REPO, "scenario", "scenario.schema.json")
        schema = load(schema_path)
        jsonschema.Draft7Validator.check_schema(schema)
        schema["$id"] = "file://" + schema_path
        registry = referencing.Registry().with_resource(
            "file://" + scenario_path, referencing.Resource.from_contents(load(scenario_path),
                                                                           referencing.jsonschema.DRAFT7))
        return jsonschema.Draft7Validator(schema, registry=registry)

    def check(self, document):
        work = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"pacsim-schema-{os.getpid()}.json")
        try:
            with open(work, "w", encoding="utf-8") as f:
                json.dump(document, f)
            run = subprocess.run([PACSIM, "--check", work], capture_output=True, text=True)
        finally:
            os.remove(work)
        self.assertIn(run.returncode, (0, 2), run.stderr)
        return run.returncode == 0

    def test_examples_are_valid(self):
        validator = self.validator()
        names = sorted(n for n in os.listdir(EXAMPLES) if n.endswith(".json"))
        self.assertGreaterEqual(len(names), 2)
        for name in names:
            with open(os.path.join(EXAMPLES, name), encoding="utf-8") as f:
                document = json.load(f)
            self.assertEqual([e.message for e in validator.iter_errors(document)], [], name)
            self.assertTrue(self.check(document), name)

    def test_schema_and_program_refuse_alike(self):
        validator = self.validator()
        damages = [
            {"controllers": [{"unit_id": 0}]}, {"controllers": [{"unit_id": 248}]}, {"controllers": [{"port": -1}]},
            {"controllers": [{"name": ""}]}, {"controllers": [{"portx": 1}]}, {"controllersx": []},
            {"controllers": []}, {"port": "5020", "controllers": [{}]},
            {"controllers": [{"timing": {"pac_cycle_ms": 0}}]},
            {"controllers": [{"modules": {"axes": 9, "ctrl": True}}]},
            {"controllers": [{"controller": {"inputs": {"1": 1}}}]},
            {"controllers": [{"rs232": {}}]}, {"controllers": [{"rs232": {"port": 1, "baud": 299}}]},
            {"controllers": [{"rs232": {"port": 1, "parity": True}}]},
            {"controllers": [{"rs232": {"port": 1, "pty": True}}]}, {"controllers": [{"rs232": {"pty": False}}]},
            {"controllers": [{"rs232": {"port": 1, "link": "x"}}]},
        ]
        for document in damages:
            self.assertFalse(validator.is_valid(document), document)
            self.assertFalse(self.check(document), document)
        accepted = [{"controllers": [{}]}, {"port": 0, "controllers": [{"unit_id": 247, "port": 65535}]},
                    {"controllers": [{"timing": {"pac_cycle_ms": 1}, "modules": {"ctrl": True, "axes": 8}}]},
                    {"controllers": [{"rs232": {"port": 0, "baud": 115200}}]},
                    {"controllers": [{"rs232": {"pty": True, "link": "pacsim-link"}}]}]
        for document in accepted:
            self.assertTrue(validator.is_valid(document), document)
            self.assertTrue(self.check(document), document)


if __name__ == "__main__":
    unittest.main()
