#include "executor.hpp"

namespace nckit::interp {

ModalView Executor::modal_view() const {
    ModalView view;
    view.length_factor_mm = modal_.length_factor_mm;
    view.work_system = modal_.work_system;
    view.work_offset = offsets_.work[modal_.work_system];
    view.work_offsets = offsets_.work;
    view.g92_offset = offsets_.g92;
    view.g52_offset = offsets_.g52;
    view.plane = modal_.plane;
    view.incremental = modal_.incremental;
    view.arc_centers_absolute = modal_.arc_centers_absolute;
    view.feed_mode = modal_.feed_mode;
    view.diameter_mode = modal_.diameter_mode;
    view.motion_code = modal_.motion;
    view.path = modal_.path;
    view.feed = modal_.feed;
    view.spindle_rpm = modal_.spindle.rpm;
    view.spindle_direction = modal_.spindle.direction;
    view.constant_surface_speed = modal_.spindle.constant_surface_speed;
    view.surface_speed_m_min = modal_.spindle.surface_speed_m_min;
    view.tool = modal_.tool.selected;
    view.tool_in_spindle = modal_.tool.in_spindle;
    view.length_offset_h = modal_.tool.h_number;
    view.length_offset_code = modal_.tool.length_mode;
    view.tool_offset = modal_.tool_offset;
    view.cutter_compensation = comp_.engaged();
    view.transform_active = transform_.active();
    view.transform = transform_.view();
    return view;
}

}  // namespace nckit::interp
