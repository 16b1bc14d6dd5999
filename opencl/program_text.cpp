#include "kernel_sources.h"

namespace collide::opencl {

std::string program_text() {
    std::string text;
    for (const auto& piece : kernel_sources()) {
        text += "#line 1 \"";
        text += piece.name;
        text += "\"\n";
        text += piece.text;
        text += "\n";
    }
    return text;
}

}  // namespace collide::opencl
