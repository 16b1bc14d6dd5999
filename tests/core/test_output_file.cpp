// core/io/output_file.h: the guard's messages name the real cause (a name too long is not "does
// not exist", a loop of links is not "a link to nothing"), the atomic write keeps the umask's
// permissions, follows a link, leaves no temporary file, and never renames over a FIFO that
// appeared while the file was being written. (tests/apps/test_output_paths.cpp runs every
// writer of the program against the same places.)
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/io/input_file.h"
#include "core/io/output_file.h"
#include "tests/support/scratch_directory.h"

namespace collide {
namespace {

namespace fs = std::filesystem;
using test::ScratchDirectory;

// The message of the OutputFileError that check_output_path(path) throws ("" if none).
std::string refusal(const std::string& path) {
    try {
        check_output_path(path);
    } catch (const OutputFileError& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(OutputFile, WritesANewFileWithTheUmasksPermissions) {
    ScratchDirectory dir;
    for (const auto& [umask, mode] : {std::pair<mode_t, mode_t>{022, 0644}, {077, 0600}}) {
        const mode_t old = ::umask(umask);
        const std::string path = dir.file("out-" + std::to_string(umask));
        write_file_atomically(path, "bytes");
        ::umask(old);
        struct stat st {};
        ASSERT_EQ(::stat(path.c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 0777, mode) << path;
        EXPECT_EQ(test::read_text_file(path), "bytes");
    }
    EXPECT_EQ(dir.entry_count(), 2u) << "no temporary file left";
}

TEST(OutputFile, FollowsALinkToARegularFileAndKeepsTheLink) {
    ScratchDirectory dir;
    const std::string real = dir.file("real"), link = dir.file("link");
    test::write_text_file(real, "old");
    fs::create_symlink("real", link);
    write_file_atomically(link, "new");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(test::read_text_file(real), "new");
    EXPECT_EQ(dir.entry_count(), 2u);
}

TEST(OutputFile, WithoutCommitTheTargetIsUntouchedAndTheTemporaryRemoved) {
    ScratchDirectory dir;
    const std::string path = dir.file("out");
    test::write_text_file(path, "old");
    {
        AtomicOutputFile file(path);
        file.write("half of it");
        EXPECT_TRUE(fs::exists(file.temporary_path()));
        EXPECT_EQ(fs::path(file.temporary_path()).parent_path(), dir.path()) << "same file system";
    }
    EXPECT_EQ(test::read_text_file(path), "old");
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(OutputFile, CommitRefusesAFifoPutInPlaceDuringTheWrite) {
    ScratchDirectory dir;
    const std::string path = dir.file("out");
    {
        AtomicOutputFile file(path);
        file.write("bytes");
        ASSERT_EQ(::mkfifo(path.c_str(), 0644), 0);
        EXPECT_THROW(file.commit(), OutputFileError);
    }
    EXPECT_TRUE(fs::is_fifo(path));
    EXPECT_EQ(dir.entry_count(), 1u);
}

TEST(OutputFile, ANameOrAPathTooLongIsCalledTooLongNotMissing) {
    ScratchDirectory dir;
    const std::string long_name = dir.file(std::string(300, 'n'));
    std::string deep = dir.path().string();
    for (int k = 0; k < 24; ++k) deep += "/" + std::string(200, 'd');  // longer than PATH_MAX
    for (const std::string& path : {long_name, deep + "/out.h5"}) {
        const std::string message = refusal(path);
        EXPECT_TRUE(contains(message, "the path is too long (File name too long")) << message;
        EXPECT_FALSE(contains(message, "does not exist")) << message;
    }
}

TEST(OutputFile, ALoopOfLinksIsCalledALoopNotALinkToNothing) {
    ScratchDirectory dir;
    const std::string a = dir.file("a"), b = dir.file("b");
    fs::create_symlink("b", a);
    fs::create_symlink("a", b);
    const std::string message = refusal(a);
    EXPECT_TRUE(contains(message, "'" + a + "': it is a loop of symbolic links")) << message;
    EXPECT_FALSE(contains(message, "to nothing")) << message;
    // A loop in the directory part is named too.
    EXPECT_TRUE(contains(refusal(a + "/out.h5"), "directory '" + a + "' is a loop of symbolic links"));
}

TEST(OutputFile, EachCauseIsNamed) {
    ScratchDirectory dir;
    test::write_text_file(dir.file("file"), "x");
    fs::create_directory(dir.file("dir"));
    fs::create_symlink("nowhere", dir.file("dangling"));
    ASSERT_EQ(::mkfifo(dir.file("fifo").c_str(), 0644), 0);
    EXPECT_TRUE(contains(refusal(dir.file("no/out")), "directory '" + dir.file("no") + "' does not exist"));
    EXPECT_TRUE(contains(refusal(dir.file("file/out")), "'" + dir.file("file") + "' is not a directory (it is a regular file)"));
    EXPECT_TRUE(contains(refusal(dir.file("dir")), "a directory of that name exists"));
    EXPECT_TRUE(contains(refusal(dir.file("dir") + "/"), "the path names a directory, not a file"));
    EXPECT_TRUE(contains(refusal(dir.file("dangling")), "a symbolic link to nothing ('nowhere' does not exist)"));
    EXPECT_TRUE(contains(refusal(dir.file("fifo")), "not a regular file (a FIFO)"));
    EXPECT_TRUE(contains(refusal(""), "the file name is empty"));
    EXPECT_EQ(refusal(dir.file("file")), "") << "a regular file is replaced";
    EXPECT_EQ(refusal(dir.file("new")), "") << "a new file is written";
}

TEST(OutputFile, AnOutputDirectoryMayBeMissingButNothingElse) {
    ScratchDirectory dir;
    ASSERT_EQ(::mkfifo(dir.file("fifo").c_str(), 0644), 0);
    fs::create_symlink("nowhere", dir.file("dangling"));
    fs::create_symlink("loop", dir.file("loop"));
    EXPECT_NO_THROW(check_output_directory(dir.file("new/and/deeper")));
    EXPECT_NO_THROW(check_output_directory(dir.path().string()));
    EXPECT_THROW(check_output_directory(dir.file("fifo")), OutputFileError);
    EXPECT_THROW(check_output_directory(dir.file("dangling")), OutputFileError);
    EXPECT_THROW(check_output_directory(dir.file("loop")), OutputFileError);
}

TEST(OutputFile, ADirectoryWithoutWritePermissionGivesTheSystemsReason) {
    if (::geteuid() == 0) GTEST_SKIP() << "root may write into read-only directories";
    ScratchDirectory dir;
    const fs::path locked = dir.path() / "locked";
    fs::create_directory(locked);
    ::chmod(locked.c_str(), 0555);
    EXPECT_TRUE(contains(refusal((locked / "out").string()), "Permission denied"));
    ::chmod(locked.c_str(), 0755);
}


// The readers' side: a scene, suite or run file that cannot be read is named with the system's
// cause, where CLI11's ExistingFile said "File does not exist" for all of these.
TEST(InputPath, EachCauseIsNamed) {
    ScratchDirectory dir;
    const std::string a = dir.file("a"), b = dir.file("b"), dangling = dir.file("dangling"), file = dir.file("f");
    fs::create_symlink("b", a);
    fs::create_symlink("a", b);
    fs::create_symlink("nowhere", dangling);
    test::write_text_file(file, "x");
    EXPECT_TRUE(contains(input_path_problem(a, false), "loop of symbolic links")) << input_path_problem(a, false);
    EXPECT_TRUE(contains(input_path_problem(dangling, false), "symbolic link to nothing"));
    EXPECT_TRUE(contains(input_path_problem(dir.file(std::string(300, 'n')), false), "too long"));
    EXPECT_TRUE(contains(input_path_problem(dir.file("missing"), false), "does not exist"));
    EXPECT_TRUE(contains(input_path_problem(file + "/x", false), "not a directory"));
    EXPECT_TRUE(contains(input_path_problem(dir.path().string(), false), "a directory, not a file"));
    EXPECT_TRUE(contains(input_path_problem(file, true), "not a directory"));
    EXPECT_EQ(input_path_problem(file, false), "");
    EXPECT_EQ(input_path_problem(dir.path().string(), true), "");
}

// The message of the exception `action` throws, "" if none.
template <typename Error>
std::string message_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// A twin of /dev/null (character device 1, 3) inside the scratch directory, never the system's
// own; false where this process may not make one (mknod needs CAP_MKNOD).
bool make_null_device(const std::string& path) { return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0; }

mode_t kind_at(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

// The files written as they go (case logs, the lock, a solver's files) pass the same guard as
// every other output, and a link is refused too: a `.lock` linked out of its directory was
// truncated, a log linked to a device written into it, a log linked to a FIFO fed its reader.
TEST(OutputStream, EveryWriterUsesTheOutputGuard) {
    ScratchDirectory dir;
    const std::string outside = dir.file("precious"), link = dir.file("linked.lock"), fifo = dir.file("fifo.log");
    const std::string device = dir.file("null.log"), device_link = dir.file("device.log");
    test::write_text_file(outside, "keep me");
    fs::create_symlink(outside, link);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    const bool have_device = make_null_device(device);
    if (have_device) fs::create_symlink(device, device_link);
    auto open_stream = [](const std::string& path) { return [path] { ::close(open_output_stream(path)); }; };
    EXPECT_TRUE(contains(message_of<OutputFileError>(open_stream(link)), "symbolic link"));
    EXPECT_EQ(test::read_text_file(outside), "keep me");
    EXPECT_TRUE(contains(message_of<OutputFileError>(open_stream(fifo)), "not a regular file (a FIFO)"));
    EXPECT_EQ(kind_at(fifo), mode_t(S_IFIFO));
    if (have_device) {
        EXPECT_TRUE(contains(message_of<OutputFileError>(open_stream(device)), "a character device"));
        EXPECT_TRUE(contains(message_of<OutputFileError>(open_stream(device_link)), "a character device"));
        EXPECT_EQ(kind_at(device), mode_t(S_IFCHR));
    }
    // A new file and an existing regular file are written; the existing one emptied first.
    const std::string log = dir.file("case.log");
    test::write_text_file(log, "old output");
    const int fd = open_output_stream(log);
    EXPECT_EQ(::write(fd, "new", 3), 3);
    ::close(fd);
    EXPECT_EQ(test::read_text_file(log), "new");
}

// A FIFO, a device or a socket is no input: refused at once, never opened to wait on.
TEST(InputFile, NonRegularInputsRefused) {
    ScratchDirectory dir;
    const std::string fifo = dir.file("scene.toml"), device = dir.file("null"), file = dir.file("f");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    test::write_text_file(file, "text");
    EXPECT_TRUE(contains(input_path_problem(fifo, false), "not a regular file (it is a FIFO)"));
    EXPECT_TRUE(contains(message_of<InputFileError>([&] { read_input_file(fifo, 100); }), "a FIFO"));
    if (make_null_device(device)) {
        EXPECT_TRUE(contains(input_path_problem(device, false), "a character device"));
        EXPECT_TRUE(contains(message_of<InputFileError>([&] { read_input_file(device, 100); }), "a character device"));
    }
    EXPECT_EQ(read_input_file(file, 100), "text");
    EXPECT_EQ(read_input_file(file, 2), "tex") << "one byte past the limit, so a caller sees the file is longer";
}

// An output that is one of the command's inputs (the same file, also through a link) is refused
// before anything is written: `collide export run.h5 --out run.h5` destroyed the only copy.
TEST(OutputFile, OutputIsNotInput) {
    ScratchDirectory dir;
    const std::string input = dir.file("run.h5"), link = dir.file("link.xyz"), other = dir.file("other.xyz");
    test::write_text_file(input, "the run");
    fs::create_symlink(input, link);
    remember_input(input);
    EXPECT_TRUE(contains(refusal(input), "it is the input '" + input + "'")) << refusal(input);
    EXPECT_TRUE(contains(refusal(link), "it is the input")) << refusal(link);
    EXPECT_TRUE(contains(message_of<OutputFileError>([&] { write_file_atomically(link, "x"); }), "it is the input"));
    EXPECT_EQ(test::read_text_file(input), "the run");
    EXPECT_EQ(refusal(other), "");
    const std::string second = dir.file("b.h5");
    test::write_text_file(second, "b");
    EXPECT_TRUE(contains(message_of<OutputFileError>([&] { check_output_is_not_input(second, second); }), "the input"));
    forget_remembered_inputs();  // the scratch files' inodes may be reused by the next test
    EXPECT_EQ(refusal(input), "");
}

// A kill during a write or its rename leaves ".NAME.tmp-PID-K": removed once its writer is
// gone, kept while the writer runs.
TEST(OutputFile, StaleTemporariesOfEndedWritersAreRemoved) {
    ScratchDirectory dir;
    const pid_t ended = ::fork();
    if (ended == 0) ::_exit(0);
    ::waitpid(ended, nullptr, 0);
    const std::string stale = ".summary.json.tmp-" + std::to_string(ended) + "-0";
    const std::string live = ".junit.xml.tmp-" + std::to_string(::getppid()) + "-3";
    for (const std::string& name : {stale, live, std::string(".notes.tmp-x-1"), std::string("summary.json")})
        test::write_text_file(dir.file(name), "x");
    EXPECT_EQ(remove_stale_temporaries(dir.path().string()), std::vector<std::string>{stale});
    EXPECT_FALSE(fs::exists(dir.file(stale)));
    for (const std::string& name : {live, std::string(".notes.tmp-x-1"), std::string("summary.json")})
        EXPECT_TRUE(fs::exists(dir.file(name))) << name;
}

}  // namespace
}  // namespace collide
