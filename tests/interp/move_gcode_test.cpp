// The plain program `nckit expand` writes: one block per move, path control kept.
#include "nckit/interp/move_gcode.hpp"

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

std::string expanded(std::string_view program, const MachineConfig& machine = default_mill()) {
    GcodeWriter writer(machine);
    std::string out;
    for (const Move& move : moves_of(program, machine)) writer.append(out, move);
    writer.append_footer(out);
    return out;
}

TEST(GcodeWriter, OneBlockPerMoveWithItsSourceLine) {
    EXPECT_EQ(expanded("G0 X1\nG1 Y2 F100\nM30\n"),
              "G0 X1.0 Y0.0 Z0.0 (test.ngc:1)\n"
              "G1 X1.0 Y2.0 Z0.0 F100.0 (test.ngc:2)\n"
              "M30 (test.ngc:3)\n");
}

TEST(GcodeWriter, ExactStopAndBlendToleranceAreWritten) {
    // G9 has no LinuxCNC twin: it becomes G61 for its move and the blend mode comes back after.
    EXPECT_EQ(expanded("G61\nG1 X10 F500\nG64 P0.02\nG1 X20\nG9 G1 X30\nG1 X40\n"),
              "G61 G1 X10.0 Y0.0 Z0.0 F500.0 (test.ngc:2)\n"
              "G64 P0.02 G1 X20.0 Y0.0 Z0.0 (test.ngc:4)\n"
              "G61 G1 X30.0 Y0.0 Z0.0 (test.ngc:5)\n"
              "G64 P0.02 G1 X40.0 Y0.0 Z0.0 (test.ngc:6)\n"
              "M30\n");
}

TEST(GcodeWriter, ArcsCarryTheirPlaneAndIncrementalCentre) {
    EXPECT_EQ(expanded("G0 X10\nG18 G2 X20 Z0 I5 K0 F200\n"),
              "G0 X10.0 Y0.0 Z0.0 (test.ngc:1)\n"
              "G18 G2 X20.0 Y0.0 Z0.0 K0.0 I5.0 F200.0 (test.ngc:2)\n"
              "M30\n");
}

TEST(GcodeWriter, ArcOfRadiusZeroIsWrittenAsTheLineItIs) {
    // LinuxCNC's compensation in a hole of the tool's diameter leaves the tool on the centre: an
    // arc of radius 0 going down in Z, which no reader takes as an arc (zero radius): a G1.
    MachineConfig machine = default_mill();
    machine.dialect = Dialect::linuxcnc;
    EXPECT_EQ(expanded("G0 X14 Y2\nG41.1 D4 G1 X10 Y2 F100\nG3 X10 Y2 I0 J-2 Z-1\nG40 G0 X20\nM2\n", machine),
              "G0 X14.0 Y2.0 Z0.0 (test.ngc:1)\n"
              "G1 X10.0 Y0.0 Z0.0 F100.0 (test.ngc:2)\n"
              "G1 X10.0 Y0.0 Z-1.0 (test.ngc:3)\n"
              "G0 X20.0 Y2.0 Z-1.0 (test.ngc:4)\n"
              "M2 (test.ngc:5)\n");
}

}  // namespace
}  // namespace nckit::test
