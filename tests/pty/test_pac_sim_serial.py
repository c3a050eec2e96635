"""pac_sim --serial over its pseudo-terminal with pyserial, as a real client: the frames of manual 3.4
byte for byte (with the errata of docs/manual_errata.md and docs/open_points.md), a frame written one byte at a time,
noise before a frame, a refused CHECK and the EOT poll.

Usage: test_pac_sim_serial.py PATH_TO_PAC_SIM
"""
import subprocess
import sys
import time
import unittest

import serial

PAC_SIM = None


def frame(text, rule="xor-etx"):
    """SOH STX text ETX CHECK EOT; CHECK the XOR of the text (and ETX), in decimal."""
    check = 0
    for c in text.encode("ascii"):
        check ^= c
    if rule == "xor-etx":
        check ^= 0x03
    elif rule == "zero":
        check = 0
    return b"\x01\x02" + text.encode("ascii") + b"\x03" + str(check).encode("ascii") + b"\x04"


def hexbytes(text):
    return bytes(int(x, 16) for x in text.split())


class PacSimSerial(unittest.TestCase):
    def setUp(self):
        # The controller's default verifies the XOR of the text alone: the rule of the manual's master frames.
        self.sim = subprocess.Popen(
            [PAC_SIM, "--serial", "--example-setup", "--until-stdin-closes", "--seconds", "60"],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        path = self.sim.stdout.readline().strip()
        self.assertTrue(path.startswith("/dev/"), path)
        self.port = serial.Serial(path, baudrate=9600, bytesize=serial.SEVENBITS, parity=serial.PARITY_NONE,
                                  stopbits=serial.STOPBITS_ONE, timeout=2.0)
        time.sleep(0.1)  # the controller boots in 50 ms

    def tearDown(self):
        self.port.close()
        self.sim.stdin.close()
        self.sim.wait(timeout=10)
        self.sim.stdout.close()

    def exchange(self, request):
        self.port.write(request)
        reply = self.port.read_until(b"\x04")
        self.assertTrue(reply.endswith(b"\x04"), reply)
        return reply

    def test_complex_example_1_of_the_manual(self):  # 3.4.2
        self.assertEqual(self.exchange(hexbytes("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 04")),
                         hexbytes("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 03 35 37 04"))
        self.assertEqual(self.exchange(frame("1906;2;0;0", "xor-text")),  # printed: 1960
                         hexbytes("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 32 32 32 03 35 38 04"))
        self.assertEqual(self.exchange(hexbytes("01 02 30 39 30 36 3B 33 3B 30 3B 33 33 33 03 34 04")),
                         hexbytes("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 33 33 33 03 35 39 04"))
        self.assertEqual(self.exchange(frame("1907;1;1;0", "xor-text")),  # printed: 1971;3;0
                         hexbytes("01 02 30 3B 31 3B 31 3B 30 3B 31 3B 36 34 30 2E 30 30 30 30 03 32 31 04"))

    def test_start_online_move_and_poll(self):  # 3.4.3
        # Printed 0A03 with CHECK 8 in the reply; the reply's CHECK is 11, the XOR with ETX.
        self.assertEqual(self.exchange(frame("0603;0;0;0", "xor-text")),
                         hexbytes("01 02 30 3B 31 3B 33 31 3B 30 3B 30 3B 30 03 31 31 04"))
        first = self.exchange(frame("0A87;2;1;100.0", "xor-text"))
        self.assertEqual(first, frame("0;0;31;0;1;0.000"))
        last = first
        for _ in range(50):
            time.sleep(0.05)
            last = self.exchange(b"\x04")
            if last.startswith(b"\x01\x020;1;"):
                break
        self.assertEqual(last, frame("0;1;31;0;1;100.000"))

    def test_a_frame_one_byte_at_a_time_after_noise(self):
        self.port.write(b"\x7f U")
        for b in frame("0906;7;0;-42", "xor-text"):
            self.port.write(bytes([b]))
            time.sleep(0.003)
        self.assertEqual(self.port.read_until(b"\x04"), frame("0;1;1;0;0;-42"))

    def test_a_refused_check_and_the_poll_that_repeats_it(self):
        self.assertEqual(self.exchange(frame("1906;2;0;0", "xor-etx")), frame("16;0;1;0;0;0"))
        self.assertEqual(self.exchange(b"\x04"), frame("16;0;1;0;0;0"))
        self.assertEqual(self.exchange(frame("1906;2;0;0", "zero")), frame("0;1;1;0;0;222"))


if __name__ == "__main__":
    PAC_SIM = sys.argv.pop(1)
    unittest.main()
