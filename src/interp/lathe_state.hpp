#pragma once
// What a lathe keeps between blocks besides the common modes: the words of the active single
// cycle (G90/G92/G94 in system A), modal as Fanuc keeps them until another group-1 code.
#include "block_words.hpp"
#include "nckit/core/axes.hpp"

namespace nckit::interp {

struct LatheSingleCycle {
    GCode mode = -1;             //!< the cycle these words belong to; -1: none has run
    AxisVector end;              //!< end point of the cut, machine coordinates, mm
    double taper_mm = 0;         //!< R: the cut starts this far (radius under G90/G92, Z under G94) from `end`
    double lead_mm = 0;          //!< G92 F: thread lead, mm per revolution
    double start_angle_deg = 0;  //!< G92 Q: spindle angle past the index at which each cut starts
};

//! The first blocks of the repetitive cycles (G71 U R, G72 W R, G73 U W R), kept until changed.
struct LatheCycleSettings {
    double rough_depth_mm = 0;       //!< G71 U / G72 W: depth of each roughing pass (radius), mm
    double retract_mm = 0;           //!< G71 R / G72 R: the 45-degree escape after each pass, mm
    double relief_x_mm = 0;          //!< G73 U: total X relief (radius), mm
    double relief_z_mm = 0;          //!< G73 W: total Z relief, mm
    int divisions = 0;               //!< G73 R: number of passes
    int finish_passes = 1;           //!< G76 P mm....: finishing passes
    double chamfer_leads = 0;        //!< G76 P ..rr..: pull-out chamfer, in leads (rr / 10)
    double thread_angle_deg = 60;    //!< G76 P ....aa: tool angle, deg
    double min_cut_mm = 0;           //!< G76 Q: smallest infeed step (radius), mm
    double thread_allowance_mm = 0;  //!< G76 R: finishing allowance (radius), mm
    double groove_retract_mm = 0;    //!< G74/G75 R: retract after each peck, mm
};

struct LatheState {
    LatheSingleCycle single;
    LatheCycleSettings settings;
};

}  // namespace nckit::interp
