// nckit_cam: nckit's electronic cam as a LinuxCNC realtime HAL component.
//
//   loadrt nckit_cam tables=/path/piston_cam.csv[,/path/other.csv] [counts=360[,3600]]
//   addf nckit-cam.0 servo-thread
//
// One instance per table file, named nckit-cam.N. The file is read and the cam engine built
// here, at load time (a bad file refuses to load, its problem printed as FILE:LINE:COL); the
// function the thread calls is a thin shim over nckit::CamFollower::step, which allocates
// nothing and reads no file. Pins and parameters are listed in docs/hal-cam.md.
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <string>

#include "nckit/cam/cam_table_file.hpp"
#include "nckit/process/fts/cam_follower.hpp"
#include "nckit/process/fts/stroke_reference.hpp"

extern "C" {
#include "hal.h"
#include "rtapi.h"
#include "rtapi_app.h"
}

namespace {

constexpr int max_instances = 8;
//! The thread period assumed until the first call says otherwise: the seed's 15 kHz.
constexpr double assumed_period_s = 1.0 / 15000.0;

//! The HAL side of one instance: pin and parameter storage lives in HAL shared memory.
struct Pins {
    // Inputs.
    hal_s32_t* counts;
    hal_bit_t* index;
    hal_float_t* revs;
    hal_bit_t* use_revs;
    hal_float_t* z;
    hal_float_t* feedback;
    hal_bit_t* reset;
    hal_bit_t* feedforward;
    hal_bit_t* learning;
    // Outputs.
    hal_float_t* command;
    hal_float_t* cam;
    hal_float_t* wanted;
    hal_float_t* error;
    hal_float_t* correction;
    hal_float_t* angle;
    hal_s32_t* count_in_turn;
    hal_float_t* speed;
    hal_bit_t* fault;
    hal_bit_t* z_fault;
    hal_bit_t* index_fault;
    hal_bit_t* input_fault;
    hal_bit_t* settings_fault;
    hal_bit_t* dac_clamped;
    hal_bit_t* learning_active;
    hal_s32_t* call_ns;
    // Parameters.
    hal_float_t model_gain;
    hal_float_t model_frequency;
    hal_float_t model_damping;
    hal_float_t learning_gain;
    hal_float_t scale;
    hal_bit_t centre;
    hal_s32_t dac_bits;
    hal_float_t dac_stroke;
    hal_s32_t index_tolerance;
};

//! The nckit side of one instance: ordinary heap memory of the rtapi_app process, built once.
struct Instance {
    std::unique_ptr<nckit::cam::CamTableFile> file;
    std::unique_ptr<nckit::cam::CamTable> table;
    std::unique_ptr<nckit::StrokeReference> reference;
    std::unique_ptr<nckit::CamFollower> follower;
    Pins* pins = nullptr;
    long period_ns = 0;
    nckit::CamFollowerOutput out;
};

int comp_id = -1;
Instance instances[max_instances];
//! ns per CPU clock (rtapi_get_clocks, the time-stamp counter): reading it costs a few ns where
//! rtapi_get_time may be a system call of hundreds. Measured at load; 0 falls back to get_time.
double ns_per_clock = 0.0;

long long now_ticks() {
    return ns_per_clock > 0.0 ? rtapi_get_clocks() : rtapi_get_time();
}

//! Times 2 ms of rtapi_get_time against rtapi_get_clocks.
void calibrate_clock() {
    const long long t0 = rtapi_get_time();
    const long long c0 = rtapi_get_clocks();
    long long t1 = t0;
    for (int i = 0; i < 100000000 && t1 - t0 < 2000000; ++i) t1 = rtapi_get_time();
    const long long c1 = rtapi_get_clocks();
    ns_per_clock = c1 > c0 && t1 > t0 ? static_cast<double>(t1 - t0) / static_cast<double>(c1 - c0) : 0.0;
}

void update(void* arg, long period) {
    const long long started = now_ticks();
    Instance& inst = *static_cast<Instance*>(arg);
    Pins& p = *inst.pins;
    if (period != inst.period_ns) {
        inst.period_ns = period;
        inst.follower->set_period(static_cast<double>(period) * 1e-9);
    }
    nckit::CamFollowerInput in;
    in.use_counts = !*p.use_revs;
    in.counts = *p.counts;
    in.index = *p.index;
    in.revolutions = *p.revs;
    in.z_mm = *p.z;
    in.feedback_mm = *p.feedback;
    in.reset_faults = *p.reset;
    nckit::CamFollowerSettings s;
    s.feedforward = *p.feedforward;
    s.learning = *p.learning;
    s.centre = p.centre;
    s.scale = p.scale;
    s.model_gain = p.model_gain;
    s.model_natural_frequency_hz = p.model_frequency;
    s.model_damping = p.model_damping;
    s.learning_gain = p.learning_gain;
    s.dac_bits = p.dac_bits;
    s.dac_stroke_mm = p.dac_stroke;
    s.index_tolerance_counts = p.index_tolerance;
    nckit::CamFollowerOutput& out = inst.out;
    inst.follower->step(in, s, out);
    *p.command = out.command_mm;
    *p.cam = out.cam_mm;
    *p.wanted = out.wanted_mm;
    *p.error = out.error_mm;
    *p.correction = out.correction_mm;
    *p.angle = out.angle_deg;
    *p.count_in_turn = static_cast<rtapi_s32>(out.count_in_turn);
    *p.speed = out.counts_per_tick;
    *p.z_fault = out.z_fault;
    *p.index_fault = out.index_fault;
    *p.input_fault = out.input_fault;
    *p.settings_fault = out.settings_fault;
    *p.dac_clamped = out.dac_clamped;
    *p.fault = out.z_fault || out.index_fault || out.input_fault || out.settings_fault || out.dac_clamped;
    *p.learning_active = out.learning_active;
    const long long spent = now_ticks() - started;
    *p.call_ns = static_cast<rtapi_s32>(ns_per_clock > 0.0 ? static_cast<double>(spent) * ns_per_clock
                                                           : static_cast<double>(spent));
}

// Module parameters (loadrt nckit_cam tables=... counts=...).
char* tables[max_instances] = {nullptr};
int counts[max_instances] = {360, 360, 360, 360, 360, 360, 360, 360};

}  // namespace

extern "C" {
RTAPI_MP_ARRAY_STRING(tables, 8, "cam table CSV files (nckit piston/eccentric --cam-table), one instance each")
RTAPI_MP_ARRAY_INT(counts, 8, "encoder counts per spindle turn of each instance (default 360)")
MODULE_AUTHOR("nckit");
MODULE_DESCRIPTION("nckit electronic cam: slaved axis from a cam table, feedforward and learning");
MODULE_LICENSE("GPL");
}

namespace {

#define NCKIT_PIN(kind, dir, field, name) \
    if (hal_pin_##kind##_newf(dir, &p->field, comp_id, "nckit-cam.%d." name, n) != 0) return -1;
#define NCKIT_PARAM(kind, field, name) \
    if (hal_param_##kind##_newf(HAL_RW, &p->field, comp_id, "nckit-cam.%d." name, n) != 0) return -1;

int export_instance(int n, Instance& inst) {
    Pins* p = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
    if (p == nullptr) return -1;
    inst.pins = p;
    NCKIT_PIN(s32, HAL_IN, counts, "spindle-counts")
    NCKIT_PIN(bit, HAL_IN, index, "spindle-index")
    NCKIT_PIN(float, HAL_IN, revs, "spindle-revs")
    NCKIT_PIN(bit, HAL_IN, use_revs, "use-revs")
    NCKIT_PIN(float, HAL_IN, z, "z")
    NCKIT_PIN(float, HAL_IN, feedback, "feedback")
    NCKIT_PIN(bit, HAL_IN, reset, "reset")
    NCKIT_PIN(bit, HAL_IN, feedforward, "feedforward-enable")
    NCKIT_PIN(bit, HAL_IN, learning, "learning-enable")
    NCKIT_PIN(float, HAL_OUT, command, "command")
    NCKIT_PIN(float, HAL_OUT, cam, "cam")
    NCKIT_PIN(float, HAL_OUT, wanted, "wanted")
    NCKIT_PIN(float, HAL_OUT, error, "error")
    NCKIT_PIN(float, HAL_OUT, correction, "correction")
    NCKIT_PIN(float, HAL_OUT, angle, "angle-deg")
    NCKIT_PIN(s32, HAL_OUT, count_in_turn, "count-in-turn")
    NCKIT_PIN(float, HAL_OUT, speed, "counts-per-period")
    NCKIT_PIN(bit, HAL_OUT, fault, "fault")
    NCKIT_PIN(bit, HAL_OUT, z_fault, "z-fault")
    NCKIT_PIN(bit, HAL_OUT, index_fault, "index-fault")
    NCKIT_PIN(bit, HAL_OUT, input_fault, "input-fault")
    NCKIT_PIN(bit, HAL_OUT, settings_fault, "settings-fault")
    NCKIT_PIN(bit, HAL_OUT, dac_clamped, "dac-clamped")
    NCKIT_PIN(bit, HAL_OUT, learning_active, "learning-active")
    NCKIT_PIN(s32, HAL_OUT, call_ns, "call-ns")
    NCKIT_PARAM(float, model_gain, "model-gain")
    NCKIT_PARAM(float, model_frequency, "model-natural-frequency-hz")
    NCKIT_PARAM(float, model_damping, "model-damping")
    NCKIT_PARAM(float, learning_gain, "learning-gain")
    NCKIT_PARAM(float, scale, "scale")
    NCKIT_PARAM(bit, centre, "centre")
    NCKIT_PARAM(s32, dac_bits, "dac-bits")
    NCKIT_PARAM(float, dac_stroke, "dac-stroke-mm")
    NCKIT_PARAM(s32, index_tolerance, "index-tolerance")
    const nckit::CamFollowerSettings defaults;
    p->model_gain = defaults.model_gain;
    p->model_frequency = defaults.model_natural_frequency_hz;
    p->model_damping = defaults.model_damping;
    p->learning_gain = defaults.learning_gain;
    p->scale = defaults.scale;
    p->centre = inst.reference != nullptr;
    p->dac_bits = defaults.dac_bits;
    p->dac_stroke = defaults.dac_stroke_mm;
    p->index_tolerance = defaults.index_tolerance_counts;
    *p->revs = 0.0;
    *p->z = inst.table->z_from_mm();
    *p->feedback = 0.0;
    char name[HAL_NAME_LEN + 1];
    rtapi_snprintf(name, sizeof(name), "nckit-cam.%d", n);
    return hal_export_funct(name, update, &inst, 1, 0, comp_id);
}

//! Reads the file and builds the cam engine; prints why not and returns false on a bad file.
bool load_table(int n, Instance& inst, const char* path) {
    nckit::Result<nckit::cam::CamTableFile> file = nckit::cam::read_cam_table_csv(path);
    if (!file) {
        for (const nckit::Diagnostic& d : file.diagnostics()) {
            rtapi_print_msg(RTAPI_MSG_ERR, "nckit_cam: %s\n", nckit::format_diagnostic(d).c_str());
        }
        return false;
    }
    inst.file = std::make_unique<nckit::cam::CamTableFile>(std::move(file).value());
    inst.table = std::make_unique<nckit::cam::CamTable>(nckit::cam::build_cam_table(*inst.file));
    if (!inst.table->meets_tolerance()) {
        rtapi_print_msg(RTAPI_MSG_WARN, "nckit_cam: %s: the cam table reaches %g mm, not its tolerance %g mm\n", path,
                        inst.table->error_bound_mm(), inst.table->tolerance_mm());
    }
    if (inst.table->z_to_mm() > inst.table->z_from_mm()) {
        inst.reference =
            std::make_unique<nckit::StrokeReference>(*inst.table, nckit::stroke_reference_points(*inst.table));
    }
    inst.follower =
        std::make_unique<nckit::CamFollower>(*inst.table, inst.reference.get(), counts[n], assumed_period_s);
    rtapi_print_msg(RTAPI_MSG_INFO, "nckit_cam: nckit-cam.%d: %s, %zu x %zu cells, error bound %g mm\n", n, path,
                    inst.table->theta_cells(), inst.table->z_cells(), inst.table->error_bound_mm());
    return true;
}

void release_instances() {
    for (Instance& inst : instances) {
        inst.follower.reset();
        inst.reference.reset();
        inst.table.reset();
        inst.file.reset();
    }
}

}  // namespace

extern "C" int rtapi_app_main(void) {
    int loaded = 0;
    for (int n = 0; n < max_instances && tables[n] != nullptr && tables[n][0] != '\0'; ++n) {
        if (counts[n] < 8) {
            rtapi_print_msg(RTAPI_MSG_ERR, "nckit_cam: counts=%d for %s: 8 or more counts per turn are needed\n",
                            counts[n], tables[n]);
            release_instances();
            return -EINVAL;
        }
        try {
            if (!load_table(n, instances[n], tables[n])) {
                release_instances();
                return -EINVAL;
            }
        } catch (const std::exception& e) {
            rtapi_print_msg(RTAPI_MSG_ERR, "nckit_cam: %s: %s\n", tables[n], e.what());
            release_instances();
            return -EINVAL;
        }
        loaded = n + 1;
    }
    if (loaded == 0) {
        rtapi_print_msg(RTAPI_MSG_ERR, "nckit_cam: give the cam table: loadrt nckit_cam tables=FILE.csv\n");
        return -EINVAL;
    }
    calibrate_clock();
    comp_id = hal_init("nckit_cam");
    if (comp_id < 0) {
        release_instances();
        return comp_id;
    }
    for (int n = 0; n < loaded; ++n) {
        if (export_instance(n, instances[n]) != 0) {
            rtapi_print_msg(RTAPI_MSG_ERR, "nckit_cam: cannot export the pins of nckit-cam.%d\n", n);
            hal_exit(comp_id);
            release_instances();
            return -EINVAL;
        }
    }
    hal_ready(comp_id);
    return 0;
}

extern "C" void rtapi_app_exit(void) {
    if (comp_id >= 0) hal_exit(comp_id);
    release_instances();
}
