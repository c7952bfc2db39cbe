#pragma once
// The process verbs' pages (`--html OUT.html`): each process's own figures and charts, on the
// same page machinery as `nckit report`. A new process adds one function here that fills a
// ReportPage (figures, charts, optionally a planned program's tool path) and its verb writes it
// with render_report_html.
#include <string>

#include "nckit/process/piston/piston_job.hpp"
#include "nckit/process/crosshatch/crosshatch.hpp"
#include "nckit/process/crosshatch/crosshatch_scan.hpp"
#include "nckit/process/eccentric/eccentric.hpp"
#include "nckit/process/notch/notch.hpp"
#include "nckit/process/piston/piston.hpp"
#include "nckit/report/report_page.hpp"

namespace nckit {

//! The section at the middle station (to scale, the deviation from D/2 magnified), the error of
//! every turn in the three runs, and the learning's convergence against its 1 µm goal.
[[nodiscard]] ReportPage piston_page(const cam::PistonJob& job, const PistonSimulation& simulation,
                                     const std::string& job_name);

//! The unrolled bore with every laser track (the net), the speeds and the timers' divisors.
[[nodiscard]] ReportPage crosshatch_page(const CrosshatchPlan& plan, const CrosshatchScan& scan,
                                         const std::string& job_name);

//! The section the cam cuts and the drawing's circle, the centre offset with and without
//! feedforward, and the X axis's cam against the spindle angle.
[[nodiscard]] ReportPage eccentric_page(const EccentricReport& report, const std::string& job_name);

//! The planned speed over every cut before and after rewriting, and (when given) the rewritten
//! program's tool path.
[[nodiscard]] ReportPage notch_page(const NotchJob& job, const std::string& program_name);

}  // namespace nckit
