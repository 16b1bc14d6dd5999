#include "image_writers.h"

#include <gif_lib.h>
#include <png.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/io/output_file.h"
#include "core/io/shell_quote.h"

namespace collide::view {
namespace {

[[noreturn]] void cannot_write(const std::string& path, const std::string& why) {
    throw std::runtime_error("cannot write '" + path + "': " + why);
}

struct FileCloser {
    void operator()(std::FILE* f) const { if (f) std::fclose(f); }
};

void write_png_file(std::FILE* file, const Image& image) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info || setjmp(png_jmpbuf(png))) {  // libpng reports errors by longjmp
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("libpng failed");
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8, PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y)
        png_write_row(png, image.rgba.data() + std::size_t(y) * std::size_t(image.width) * 4);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
}

class GifWriter : public AnimationWriter {
public:
    GifWriter(const std::string& path, int width, int height, double fps)
        : path_(path), temp_(path), width_(width), height_(height),
          delay_(std::max(2, int(std::lround(100 / fps)))) {
        // Opened here, not by EGifOpenFileName, which would create the file readable by its
        // owner only; AtomicOutputFile created it with the umask's permissions.
        const int fd = ::open(temp_.temporary_path().c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (fd < 0) cannot_write(path, std::strerror(errno));
        int error = 0;
        gif_ = EGifOpenFileHandle(fd, &error);
        if (!gif_) {
            ::close(fd);
            cannot_write(path, GifErrorString(error));
        }
        EGifSetGifVersion(gif_, true);  // GIF89a: needed for frame delays and looping
        check(EGifPutScreenDesc(gif_, width, height, 8, 0, nullptr));
        // The NETSCAPE2.0 application block: loop forever.
        static const unsigned char netscape[] = "NETSCAPE2.0", loop[] = {1, 0, 0};
        check(EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE));
        check(EGifPutExtensionBlock(gif_, 11, netscape));
        check(EGifPutExtensionBlock(gif_, 3, loop));
        check(EGifPutExtensionTrailer(gif_));
    }
    ~GifWriter() override {
        if (gif_) EGifCloseFile(gif_, nullptr);
    }

    // Each frame gets its own 256-colour table (median cut): the colour map has many more
    // shades than one global table could hold across frames.
    void add(const Image& frame) override {
        const std::size_t n = std::size_t(width_) * std::size_t(height_);
        std::vector<GifByteType> r(n), g(n), b(n), indices(n);
        for (std::size_t k = 0; k < n; ++k) {
            r[k] = frame.rgba[4 * k];
            g[k] = frame.rgba[4 * k + 1];
            b[k] = frame.rgba[4 * k + 2];
        }
        int colors = 256;
        GifColorType map[256] = {};
        check(GifQuantizeBuffer(unsigned(width_), unsigned(height_), &colors, r.data(), g.data(), b.data(),
                                indices.data(), map));
        GraphicsControlBlock gcb{DISPOSE_DO_NOT, false, delay_, NO_TRANSPARENT_COLOR};
        GifByteType extension[4];
        const std::size_t length = EGifGCBToExtension(&gcb, extension);
        check(EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, int(length), extension));
        ColorMapObject* colour_map = GifMakeMapObject(256, map);
        const int status = EGifPutImageDesc(gif_, 0, 0, width_, height_, false, colour_map);
        GifFreeMapObject(colour_map);
        check(status);
        check(EGifPutLine(gif_, indices.data(), int(n)));
    }

    void finish() override {
        int error = 0;
        const int status = EGifCloseFile(gif_, &error);
        gif_ = nullptr;
        if (status != GIF_OK) cannot_write(path_, GifErrorString(error));
        temp_.commit();
    }

private:
    void check(int status) {
        if (status == GIF_ERROR) cannot_write(path_, GifErrorString(gif_->Error));
    }

    std::string path_;
    AtomicOutputFile temp_;
    int width_, height_, delay_;  // delay in hundredths of a second, GIF's unit
    GifFileType* gif_ = nullptr;
};

// MP4 by piping raw RGBA frames into ffmpeg (H.264, yuv420p so that browsers play it; that
// format needs even sizes, hence the pad filter).
class Mp4Writer : public AnimationWriter {
public:
    Mp4Writer(const std::string& path, int width, int height, double fps) : path_(path), temp_(path) {
        const std::string command = "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgba -s " + std::to_string(width) +
                                    "x" + std::to_string(height) + " -r " + std::to_string(fps) +
                                    " -i - -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p -f mp4 " +
                                    shell_quote(temp_.temporary_path());
        // A failed ffmpeg closes the pipe; without this the next write would kill us silently
        // (SIGPIPE) instead of failing with a message.
        std::signal(SIGPIPE, SIG_IGN);
        pipe_ = ::popen(command.c_str(), "w");
        if (!pipe_) cannot_write(path, "cannot start ffmpeg");
    }
    ~Mp4Writer() override {
        if (pipe_) ::pclose(pipe_);
    }
    void add(const Image& frame) override {
        if (std::fwrite(frame.rgba.data(), 1, frame.rgba.size(), pipe_) != frame.rgba.size())
            cannot_write(path_, "ffmpeg stopped reading frames");
    }
    void finish() override {
        const int status = ::pclose(pipe_);
        pipe_ = nullptr;
        if (status != 0) cannot_write(path_, "ffmpeg failed (exit status " + std::to_string(status) + ")");
        temp_.commit();
    }

private:
    std::string path_;
    AtomicOutputFile temp_;  // ffmpeg writes the temporary file; finish() renames it
    std::FILE* pipe_ = nullptr;
};

}  // namespace

void write_png(const std::string& path, const Image& image) {
    AtomicOutputFile temp(path);
    {
        std::unique_ptr<std::FILE, FileCloser> file(std::fopen(temp.temporary_path().c_str(), "wb"));
        if (!file) cannot_write(path, "cannot create the file");
        try {
            write_png_file(file.get(), image);
        } catch (const std::exception& e) {
            cannot_write(path, e.what());
        }
        if (std::fflush(file.get()) != 0) cannot_write(path, "write failed");
    }
    temp.commit();
}

std::unique_ptr<AnimationWriter> open_gif(const std::string& path, int width, int height, double fps) {
    return std::make_unique<GifWriter>(path, width, height, fps);
}

std::unique_ptr<AnimationWriter> open_mp4(const std::string& path, int width, int height, double fps) {
    if (!ffmpeg_available()) cannot_write(path, "MP4 needs ffmpeg, which is not installed (write .gif or .png instead)");
    return std::make_unique<Mp4Writer>(path, width, height, fps);
}

bool ffmpeg_available() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

std::string output_format(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png" || ext == ".gif" || ext == ".mp4") return ext.substr(1);
    cannot_write(path, "unknown output format '" + ext + "' (use .gif, .mp4 or .png)");
}

}  // namespace collide::view
