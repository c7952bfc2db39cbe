// nckit_servo: nckit's second-order axis model k / (T² s² + 2 ζ T s + 1) as a HAL component,
// discretised exactly for the thread's period (nckit::drive::ServoModel, the model nckit's
// simulations use). It stands in for a fast tool servo in a sim configuration:
//
//   loadrt nckit_servo count=1
//   addf nckit-servo.0 servo-thread
//   net fts-cmd nckit-cam.0.command => nckit-servo.0.command
//   net fts-pos nckit-servo.0.position => nckit-cam.0.feedback
#include <cmath>
#include <optional>

#include "nckit/drive/servo_model.hpp"

extern "C" {
#include "hal.h"
#include "rtapi.h"
#include "rtapi_app.h"
}

namespace {

constexpr int max_instances = 8;

struct Pins {
    hal_float_t* command;
    hal_float_t* position;
    hal_float_t* velocity;
    hal_float_t gain;
    hal_float_t natural_frequency;
    hal_float_t damping;
};

struct Instance {
    Pins* pins = nullptr;
    std::optional<nckit::drive::ServoModel> model;  //!< rebuilt (in place) when a parameter or the period changes
    nckit::drive::ServoParameters used{};
    double used_frequency_hz = 0.0;
    long period_ns = 0;
};

int comp_id = -1;
Instance instances[max_instances];

void update(void* arg, long period) {
    Instance& inst = *static_cast<Instance*>(arg);
    Pins& p = *inst.pins;
    const double gain = p.gain;
    const double frequency = p.natural_frequency;
    const double damping = p.damping;
    const bool valid = std::isfinite(gain) && gain > 0.0 && std::isfinite(frequency) && frequency > 0.0 &&
                       std::isfinite(damping) && damping >= 0.0;
    const bool changed = !inst.model || period != inst.period_ns || gain != inst.used.gain ||
                         damping != inst.used.damping || frequency != inst.used_frequency_hz;
    if (valid && changed) {
        const nckit::drive::ServoState state = inst.model ? inst.model->state() : nckit::drive::ServoState{};
        const double setpoint = inst.model ? inst.model->following_error() + state.position : 0.0;
        inst.used = nckit::drive::ServoParameters::from_natural_frequency(gain, frequency, damping);
        inst.used_frequency_hz = frequency;
        inst.period_ns = period;
        inst.model.emplace(inst.used, static_cast<double>(period) * 1e-9, state);
        inst.model->reset(state, setpoint);
    }
    if (!inst.model) return;  // never valid yet: the outputs stay at 0
    const double command = *p.command;
    const nckit::drive::ServoState s = inst.model->step(std::isfinite(command) ? command : 0.0);
    *p.position = s.position;
    *p.velocity = s.velocity;
}

int count = 1;

}  // namespace

extern "C" {
RTAPI_MP_INT(count, "number of axis models (nckit-servo.0 ...)")
MODULE_AUTHOR("nckit");
MODULE_DESCRIPTION("nckit second-order axis model, exact zero-order-hold discretisation");
MODULE_LICENSE("GPL");
}

extern "C" int rtapi_app_main(void) {
    if (count < 1 || count > max_instances) {
        rtapi_print_msg(RTAPI_MSG_ERR, "nckit_servo: count must lie in 1 .. %d\n", max_instances);
        return -EINVAL;
    }
    comp_id = hal_init("nckit_servo");
    if (comp_id < 0) return comp_id;
    for (int n = 0; n < count; ++n) {
        Pins* p = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
        instances[n].pins = p;
        char name[HAL_NAME_LEN + 1];
        rtapi_snprintf(name, sizeof(name), "nckit-servo.%d", n);
        if (p == nullptr || hal_pin_float_newf(HAL_IN, &p->command, comp_id, "%s.command", name) != 0 ||
            hal_pin_float_newf(HAL_OUT, &p->position, comp_id, "%s.position", name) != 0 ||
            hal_pin_float_newf(HAL_OUT, &p->velocity, comp_id, "%s.velocity", name) != 0 ||
            hal_param_float_newf(HAL_RW, &p->gain, comp_id, "%s.gain", name) != 0 ||
            hal_param_float_newf(HAL_RW, &p->natural_frequency, comp_id, "%s.natural-frequency-hz", name) != 0 ||
            hal_param_float_newf(HAL_RW, &p->damping, comp_id, "%s.damping", name) != 0 ||
            hal_export_funct(name, update, &instances[n], 1, 0, comp_id) != 0) {
            hal_exit(comp_id);
            return -EINVAL;
        }
        p->gain = 1.0;
        p->natural_frequency = 135.0;
        p->damping = 0.3;
    }
    hal_ready(comp_id);
    return 0;
}

extern "C" void rtapi_app_exit(void) {
    if (comp_id >= 0) hal_exit(comp_id);
}
