// Writing frames to files: PNG (libpng), animated GIF (giflib) and MP4 (through an `ffmpeg`
// process, only where one is installed). Every file goes through the output guard and the
// atomic rename of core/io/output_file.h: a device, a FIFO or a link to nothing is refused when
// the writer opens, the file is written under a temporary name in the target's directory and
// renamed when complete, so a failure never leaves half a file.
#pragma once

#include <memory>
#include <string>

#include "canvas.h"

namespace collide::view {

void write_png(const std::string& path, const Image& image);

class AnimationWriter {
public:
    virtual ~AnimationWriter() = default;
    virtual void add(const Image& frame) = 0;  // every frame has the size given at opening
    virtual void finish() = 0;                 // completes the file and moves it into place
};

std::unique_ptr<AnimationWriter> open_gif(const std::string& path, int width, int height, double fps);
std::unique_ptr<AnimationWriter> open_mp4(const std::string& path, int width, int height, double fps);

// Whether an `ffmpeg` program is on PATH (MP4 output needs it).
bool ffmpeg_available();

// Picks "png", "gif" or "mp4" from the extension of `path`; throws, naming the file and the
// formats there are, for anything else.
std::string output_format(const std::string& path);

}  // namespace collide::view
