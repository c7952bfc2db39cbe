#!/usr/bin/env python3
"""The tool-data rule of the real-program corpus (program_tools.py) on small texts: which D
offsets a program's own words set, to what diameter, and when a Fusion 360 program counts as
posted with Wear compensation. Exit status 0 when every case holds."""

import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import program_tools as pt  # noqa: E402


def derive(text: str, fusion: bool = False) -> pt.ToolData:
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "p.nc"
        path.write_text(text)
        return pt.derive(path, fusion)


class Sizes(unittest.TestCase):
    def test_fractions_decimals_and_units(self):
        self.assertAlmostEqual(pt.size_mm('= 1/2"  END MILL 03-0086', False), 12.7)
        self.assertAlmostEqual(pt.size_mm("= .5 ENDMILL 03-0086", True), 12.7)
        self.assertAlmostEqual(pt.size_mm("= 3/8IN ENDMILL", False), 9.525)
        self.assertAlmostEqual(pt.size_mm("drill with a diameter == 5mm", True), 5.0)
        self.assertAlmostEqual(pt.size_mm("| 3. FLAT ENDMILL |", False), 3.0)

    def test_counts_and_part_numbers_are_no_size(self):
        self.assertIsNone(pt.size_mm("END MILL 3 FLUTES 03-0086", True))
        self.assertIsNone(pt.size_mm("Activate cutter comp for D05. Move", True))
        self.assertIsNone(pt.size_mm("#10 drill", True))


class Offsets(unittest.TestCase):
    def test_tool_list_comment_sets_the_d_used_with_that_tool(self):
        d = derive('%\nO1 (T01 = 1/2"  END MILL)\nG20\nT01 M06\nG0 X-1 Y-1\nG41 D01 X0\nY1\nG40 X-1\nM30\n')
        self.assertEqual(d.diameters_mm, {1: 12.7})

    def test_comment_on_the_tool_change_line_and_a_lone_m6(self):
        d = derive("G20\nM06 T3 (1/4\" end mill)\nG41 D3 X0\nG40 X1\nT4 (3/8 END MILL)\nM6\nG41 D1 X0\n")
        self.assertEqual(sorted(d.diameters_mm), [1, 3])
        self.assertAlmostEqual(d.diameters_mm[3], 6.35)
        self.assertAlmostEqual(d.diameters_mm[1], 9.525)

    def test_preselected_tool_is_not_in_the_spindle(self):
        d = derive("G21\n(T1 D=10. CR=0. - FLAT END MILL)\n(T2 D=4. CR=0. - FLAT END MILL)\n"
                   "T1 M06\nT2\nG0 X-20 Y0\nG1 G41 X0 D11\nX10\n", fusion=True)
        self.assertEqual(d.diameters_mm, {11: 10.0})

    def test_no_stated_size_keeps_the_table(self):
        self.assertEqual(derive("G20\nT5 M06 (Change to end mill)\nG41 D05 X0\n").diameters_mm, {})


class FusionWear(unittest.TestCase):
    PROGRAM = ("G21\n(T8 D=16. CR=0. - ZMIN=73.5 - FLAT END MILL)\nT8 M06\nG00 X-13.35 Y-39.6\n"
               "G01 G41 X-10.15 Y-40.4 D08\nG03 X-7.75 Y-38. J{j}\nG01 Y-0.5\n")

    def test_lead_in_arc_smaller_than_the_tool_means_wear(self):
        d = derive(self.PROGRAM.format(j="2.4"), fusion=True)
        self.assertEqual(d.diameters_mm, {8: 0.0})
        self.assertIn("Wear", d.reasons[8])

    def test_larger_lead_in_arc_is_compensation_in_control(self):
        self.assertEqual(derive(self.PROGRAM.format(j="9."), fusion=True).diameters_mm, {8: 16.0})

    def test_the_rule_is_fusions_only(self):
        self.assertEqual(derive(self.PROGRAM.format(j="2.4"), fusion=False).diameters_mm, {8: 16.0})


class Table(unittest.TestCase):
    def test_rows_are_replaced_or_added(self):
        with tempfile.TemporaryDirectory() as tmp:
            base = Path(tmp) / "base.tbl"
            base.write_text("T1 P1 Z+41.000 D+6.350 ;tool 1\nT2 P2 Z+42.000 D+6.350 ;tool 2\n")
            data = pt.ToolData({2: 12.7, 44: 0.0}, {})
            rows = pt.write_table(base, data, Path(tmp) / "out.tbl").read_text().splitlines()
        self.assertEqual(rows, ["T1 P1 Z+41.000 D+6.350 ;tool 1", "T2 P2 Z+42.000 D+12.7000 ;tool 2",
                                "T44 P44 Z+84.000 D+0.0000 ;offset 44"])


if __name__ == "__main__":
    unittest.main()
