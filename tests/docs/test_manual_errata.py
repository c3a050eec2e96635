"""ManualErrata.Recompute: every checked table of docs/manual_errata.md recomputed from first principles
(IEEE-754 single precision, the CMD flag word of manual 2.4.2, hex against decimal, the XOR CHECK of an
RS232 frame), so a wrong figure on the page fails CI. A table is checked when the line before it reads
<!-- checked: NAME -->; each NAME below must be there with at least its number of rows."""
import os
import re
import struct
import sys
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PAGE = os.path.join(REPO, "docs", "manual_errata.md")


def read_tables(path):
    """{name: [row dicts keyed by the header's cells]} for every table after a 'checked' marker."""
    tables = {}
    with open(path, encoding="utf-8") as page:
        lines = page.read().splitlines()
    for i, line in enumerate(lines):
        marker = re.fullmatch(r"<!-- checked: ([a-z0-9-]+) -->", line.strip())
        if not marker:
            continue
        header = [c.strip() for c in lines[i + 1].strip().strip("|").split("|")]
        rows = []
        for row in lines[i + 3:]:
            if not row.startswith("|"):
                break
            rows.append(dict(zip(header, (c.strip() for c in row.strip().strip("|").split("|")))))
        tables[marker.group(1)] = rows
    return tables


def decode(hex_bytes):
    return struct.unpack(">f", bytes.fromhex(hex_bytes))[0]


def encode(value):
    return struct.pack(">f", float(value)).hex(" ").upper()


def xor(text):
    result = 0
    for byte in text.encode("ascii"):
        result ^= byte
    return result


class ManualErrata(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tables = read_tables(PAGE)

    def table(self, name, min_rows):
        rows = self.tables.get(name, [])
        self.assertGreaterEqual(len(rows), min_rows, f"table '{name}' missing or cut short in {PAGE}")
        return rows

    def test_wrong_ieee_examples(self):
        for row in self.table("ieee-wrong", 9):
            printed, value = float(row["value printed"]), decode(row["bytes printed"])
            with self.subTest(row=row):
                self.assertEqual(value, float(row["the bytes are"]), "what the printed bytes decode to")
                self.assertNotEqual(value, struct.unpack(">f", struct.pack(">f", printed))[0],
                                    "the print is listed as wrong but is right")
                self.assertEqual(encode(printed), row["the printed value is"], "the printed value's bytes")

    def test_right_ieee_examples(self):
        for row in self.table("ieee-right", 7):
            with self.subTest(row=row):
                self.assertEqual(encode(row["value printed"]), row["bytes printed"])

    def test_cmd_flag_word(self):
        for row in self.table("cmd-flags", 3):
            word = (int(row["RECEIVE"]) << 15 | int(row["command error"]) << 14
                    | int(row["END OF PROCESSING"]) << 13 | int(row["error number"]))
            with self.subTest(row=row):
                self.assertEqual(f"{word >> 8:02X} {word & 0xFF:02X}", row["bytes 6, 7"])

    def test_error_numbers(self):
        for row in self.table("error-numbers", 4):
            printed_hex = row["printed hex"].split()[0]
            with self.subTest(row=row):
                self.assertNotEqual(int(printed_hex, 16), int(row["printed decimal"]), "the print agrees")
                self.assertEqual(int(row["right hex"], 16), int(row["right decimal"]))

    def test_rs232_checks(self):
        rows = self.table("rs232-frames", 17)
        for row in rows:
            with self.subTest(row=row):
                self.assertEqual(xor(row["text as printed"]), int(row["XOR of the text"]))
                self.assertEqual(xor(row["text as printed"]) ^ 0x03, int(row["XOR with ETX"]))
        # The counts the page states in words.
        acks = [r for r in rows if r["frame"] == "acknowledgement"]
        masters = [r for r in rows if r["frame"] == "master"]
        self.assertEqual((len(acks), sum(r["CHECK printed"] == r["XOR with ETX"] for r in acks)), (10, 9))
        self.assertEqual(len(masters), 7)
        self.assertEqual(sum(r["CHECK printed"] == r["XOR of the text"] for r in masters), 3)
        self.assertEqual(sum(r["CHECK printed"] == r["XOR with ETX"] for r in masters), 0)
        # The texts meant, where the print is wrong (the page's list below the table).
        self.assertEqual(xor("0603;0;0;0"), 14)
        self.assertEqual(xor("1907;1;0;0") ^ 0x03, 6)
        self.assertNotIn(6, (xor("1906;2;0;0"), xor("1906;2;0;0") ^ 0x03))


if __name__ == "__main__":
    result = unittest.main(argv=[sys.argv[0], "-v"], exit=False).result
    sys.exit(0 if result.wasSuccessful() else 1)
