"""The report's twin of core/io/output_file.h: one guard and one atomic write for every file the
Python side of collide writes (the report's HTML and Markdown, numbers written into a page).

check_output_path(path) accepts a new file in an existing, writable directory, an existing
regular file and a symbolic link to one; it refuses everything else with the same words as
the C++ guard (docs/refusals.md, "Output paths"): a missing directory, a path through a file,
a directory, a character or block device, a FIFO or a socket in the way, a symbolic link to
nothing, a loop of symbolic links, a name too long, a directory without write permission. A
plain open(path, "w") would write into a device, block forever on a FIFO, or create the file
a dangling link points to.

write_text(path, text) / write_bytes(path, data) write a temporary ".NAME.tmp-PID-K" in the
target's own directory (created with mode 0666 less the umask), fsync it and os.replace() it
over the target: a reader sees the old file or the new one, never half of one. A symbolic link
is followed, so the file it points to is replaced and the link stays a link. On any failure
the temporary file is removed. atomic_output(path) does the same for a writer that writes a
file by its name (the GSD writer): it yields the temporary's path.

The readers' side (core/io/input_file.h in C++): open_input(path, mode) opens only a regular
file (or a link to one) and never waits on a FIFO; check_input_file(path) checks a file another
library opens (h5py). A FIFO, a device or a socket raises InputPathError, an OSError whose
strerror says what the path is.

This module needs nothing but the standard library: the report renderer (validation/report)
and the GSD writer import it from this folder.
"""
import contextlib
import errno
import itertools
import os
import stat

_counter = itertools.count()


class OutputPathError(Exception):
    """A refused path or a failed write; the message names the path and the cause."""


def _refuse(path, why):
    raise OutputPathError(f"cannot write '{path}': {why}")


def _kind(mode):
    for test, name in ((stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISFIFO, "a FIFO"), (stat.S_ISSOCK, "a socket"), (stat.S_ISDIR, "a directory"),
                       (stat.S_ISREG, "a regular file")):
        if test(mode):
            return name
    return "not a regular file"


def _too_long():
    name_max = os.pathconf("/", "PC_NAME_MAX")
    path_max = os.pathconf("/", "PC_PATH_MAX")
    return (f"the path is too long ({os.strerror(errno.ENAMETOOLONG)}: at most {name_max} bytes a name "
            f"and {path_max - 1} bytes a path)")


def _link_loop(what):
    return f"{what} is a loop of symbolic links ({os.strerror(errno.ELOOP)}): it never reaches a file"


def _unreachable_directory(directory, e):
    if e.errno == errno.ENAMETOOLONG:
        return _too_long()
    if e.errno == errno.ELOOP:
        return _link_loop(f"directory '{directory}'")
    if e.errno == errno.ENOTDIR:
        return f"a part of '{directory}' is not a directory"
    if e.errno == errno.EACCES:
        return f"directory '{directory}' cannot be searched ({e.strerror})"
    return f"directory '{directory}': {e.strerror}"


def _directory_of(path):
    return os.path.dirname(os.fspath(path)) or "."


def _link_to_nothing(path):
    return f"it is a symbolic link to nothing ('{os.readlink(path)}' does not exist)"


def _check_writable(path, directory, what):
    """Creating `what` in `directory` needs write and search permission on it (POSIX open(2))."""
    if not os.access(directory, os.W_OK | os.X_OK):
        _refuse(path, f"cannot create {what} in directory '{directory}' ({os.strerror(errno.EACCES)})")


def _check_directory_of(path, directory):
    try:
        st = os.stat(directory)
    except OSError as e:
        if e.errno == errno.ENOENT:
            _refuse(path, f"directory '{directory}' does not exist")
        _refuse(path, _unreachable_directory(directory, e))
    if not stat.S_ISDIR(st.st_mode):
        _refuse(path, f"'{directory}' is not a directory (it is {_kind(st.st_mode)})")
    _check_writable(path, directory, "a file")


def _follow_link(path):
    try:
        return os.stat(path)
    except OSError as e:
        if e.errno == errno.ELOOP:
            _refuse(path, _link_loop("it"))
        if e.errno == errno.ENAMETOOLONG:
            _refuse(path, _too_long())
        if e.errno == errno.ENOENT:
            _refuse(path, _link_to_nothing(path))
        _refuse(path, f"it is a symbolic link to '{os.readlink(path)}', which cannot be reached ({e.strerror})")


def _check_existing(path):
    """The file at `path`, if any, must be a regular file or a link to one: the new file is
    renamed over it, which would turn a device or a FIFO into a plain file."""
    try:
        st = os.lstat(path)
    except OSError as e:
        if e.errno == errno.ENOENT:
            return
        _refuse(path, _too_long() if e.errno == errno.ENAMETOOLONG else e.strerror)
    if stat.S_ISLNK(st.st_mode):
        st = _follow_link(path)
    if stat.S_ISDIR(st.st_mode):
        _refuse(path, "a directory of that name exists")
    if not stat.S_ISREG(st.st_mode):
        _refuse(path, f"it exists and is not a regular file ({_kind(st.st_mode)}); "
                      "collide writes only to a new or a regular file")


def _followed(path):
    return os.path.realpath(path) if os.path.islink(path) else path


def check_output_path(path):
    """Raises OutputPathError when `path` is no place to write a file (module docstring)."""
    path = os.fspath(path)
    if not path:
        raise OutputPathError("cannot write the output: the file name is empty")
    if path.endswith(os.sep):
        _refuse(path, "the path names a directory, not a file")
    _check_directory_of(path, _directory_of(path))
    _check_existing(path)
    target = _followed(path)
    if target != path:
        _check_directory_of(path, _directory_of(target))


def check_output_directory(path):
    """An output directory may be missing (it is created), but what exists under its name must
    be a directory or a link to one."""
    path = os.fspath(path)
    if not path:
        raise OutputPathError("cannot write into the output directory: its name is empty")
    try:
        st = os.stat(path)
    except OSError as e:
        if e.errno == errno.ENOENT and os.path.islink(path):
            _refuse(path, _link_to_nothing(path))
        if e.errno == errno.ENOENT:
            return
        _refuse(path, _unreachable_directory(path, e))
    if not stat.S_ISDIR(st.st_mode):
        _refuse(path, f"it exists and is not a directory (it is {_kind(st.st_mode)}); expected an output directory")
    _check_writable(path, path, "files")


def make_output_directory(path):
    """check_output_directory, then the directory created with its parents."""
    check_output_directory(path)
    os.makedirs(path, exist_ok=True)


class InputPathError(OSError):
    """An input that is no regular file; strerror names what it is, filename the path."""


def _not_regular(path, mode):
    what = "a directory, not a file" if stat.S_ISDIR(mode) else \
        f"not a regular file (it is {_kind(mode)}); collide reads only regular files"
    return InputPathError(errno.EINVAL, what, os.fspath(path))


def check_input_file(path):
    """Raises InputPathError (or the OSError of a failed stat) unless `path` is a regular file."""
    st = os.stat(path)
    if not stat.S_ISREG(st.st_mode):
        raise _not_regular(path, st.st_mode)


def open_input(path, mode="rb", encoding=None):
    """open(path, mode) for reading, refusing what is no regular file without waiting on it: the
    open is non-blocking, and what was opened is checked (a FIFO put there after a check too)."""
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC | os.O_NOCTTY)
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise _not_regular(path, st.st_mode)
        os.set_blocking(fd, True)
        return os.fdopen(fd, mode, encoding=encoding)
    except BaseException:
        os.close(fd)
        raise


@contextlib.contextmanager
def atomic_output(path):
    """Yields a temporary path in the target's directory for the caller to write; when the block
    ends without an exception, the target is checked again (something may have been put there
    meanwhile) and the temporary renamed over it (a link's target, the link kept). The
    temporary is removed on any failure."""
    path = os.fspath(path)
    check_output_path(path)
    target = _followed(path)
    temporary = os.path.join(_directory_of(target),
                             f".{os.path.basename(target)}.tmp-{os.getpid()}-{next(_counter)}")
    try:
        os.close(os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC, 0o666))
    except OSError as e:
        _refuse(path, f"cannot create '{temporary}' ({e.strerror})")
    try:
        yield temporary
        _check_existing(path)
        os.replace(temporary, target)
    except OSError as e:
        if isinstance(e, OutputPathError):
            raise
        _refuse(path, e.strerror or str(e))
    finally:
        if os.path.lexists(temporary):
            os.unlink(temporary)


def write_bytes(path, data):
    """`data` written atomically at `path` (module docstring)."""
    with atomic_output(path) as temporary:
        fd = os.open(temporary, os.O_WRONLY | os.O_CLOEXEC)
        try:
            view = memoryview(data)
            while view:
                view = view[os.write(fd, view):]
            os.fsync(fd)  # complete on disk before the rename, even if the power fails
        finally:
            os.close(fd)


def write_text(path, text, encoding="utf-8"):
    write_bytes(path, text.encode(encoding))
