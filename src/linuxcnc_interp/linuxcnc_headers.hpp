#pragma once
// LinuxCNC's headers, included in one place: they are C-era headers built with ULAPI defined, and
// they warn under nckit's warning set, so they are read as system headers.
#pragma GCC system_header
#include <canon.hh>
#include <interp_base.hh>
#include <interp_return.hh>
