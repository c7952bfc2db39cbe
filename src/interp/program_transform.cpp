// Mirror, scale and rotation of programmed points (Fanuc G51.1, G51, G68).
#include "program_transform.hpp"

namespace nckit::interp {

bool ProgramTransform::sets_transform(const BlockWords& words) {
    if (words.group(ModalGroup::scaling) >= 0 || words.group(ModalGroup::mirror) >= 0 ||
        words.group(ModalGroup::rotation) >= 0) {
        return true;
    }
    // G50 alone cancels scaling (Fanuc mills); with S it clamps the spindle, with axis words it
    // sets coordinates (lathes).
    if (words.group(ModalGroup::non_modal) != g(50) || words.has('S')) return false;
    for (char c : axis_letters) {
        if (words.has(c)) return false;
    }
    return true;
}

}  // namespace nckit::interp
