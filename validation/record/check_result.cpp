#include "validation/record/check_result.h"

namespace collide::validation {

const char* to_string(CheckStatus s) {
    switch (s) {
        case CheckStatus::pass: return "pass";
        case CheckStatus::fail: return "fail";
        default: return "left_out";
    }
}

}  // namespace collide::validation
