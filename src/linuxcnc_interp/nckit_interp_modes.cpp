// The modes LinuxCNC shows of the interpreter (active_g_codes, active_m_codes, active_settings):
// those of the block last read, in LinuxCNC's layout.
#include "nckit_interp.hpp"

namespace nckit::lcnc {

void NckitInterp::active_g_codes(int g[ACTIVE_G_CODES]) {
    const ModalView& v = view_;
    g[0] = sequence_;
    g[1] = v.motion_code;
    g[2] = -1;
    g[3] = v.plane == Plane::xy ? 170 : v.plane == Plane::zx ? 180 : 190;
    g[4] = 400;
    g[5] = v.length_factor_mm != 1.0 ? 200 : 210;
    g[6] = v.incremental ? 910 : 900;
    g[7] = v.feed_mode == FeedMode::per_revolution ? 950 : 940;
    g[8] = 540 + 10 * static_cast<int>(v.work_system);
    g[9] = 490;
    g[10] = 980;
    g[11] = v.path.exact_stop ? 611 : 640;
    g[12] = -1;
    g[13] = v.constant_surface_speed ? 960 : 970;
    g[14] = 911;
    g[15] = v.diameter_mode ? 70 : 80;
    g[16] = -1;
}

void NckitInterp::active_m_codes(int m[ACTIVE_M_CODES]) {
    int direction = canon_ ? canon_->spindle_direction() : 0;
    bool mist = canon_ && canon_->mist();
    bool flood = canon_ && canon_->flood();
    m[0] = sequence_;
    m[1] = -1;
    m[2] = direction > 0 ? 3 : direction < 0 ? 4 : 5;
    m[3] = -1;
    m[4] = mist ? 7 : flood ? -1 : 9;
    m[5] = flood ? 8 : -1;
    m[6] = 48;
    for (int i = 7; i < ACTIVE_M_CODES; ++i) m[i] = -1;
}

void NckitInterp::active_settings(double s[ACTIVE_SETTINGS]) {
    const ModalView& v = view_;
    s[0] = sequence_;
    s[1] = v.feed / v.length_factor_mm;
    s[2] = v.constant_surface_speed ? v.surface_speed_m_min : v.spindle_rpm;
    s[3] = v.path.tolerance_mm / v.length_factor_mm;
    s[4] = s[3];
}

// The state tags of LinuxCNC's own interpreter (modes carried with each motion): none here, so
// LinuxCNC shows the modes of the block last read, as it does outside AUTO mode.
int NckitInterp::active_modes(int[ACTIVE_G_CODES], int[ACTIVE_M_CODES], double[ACTIVE_SETTINGS], StateTag const&) {
    return INTERP_ERROR;
}
int NckitInterp::restore_from_tag(StateTag const&) {
    return INTERP_OK;
}
void NckitInterp::print_state_tag(StateTag const&) {}
void NckitInterp::set_loglevel(int) {}
// nckit's main program always restarts at M99, as a Fanuc control's does.
void NckitInterp::set_loop_on_main_m99(bool) {}

}  // namespace nckit::lcnc
