"""python/collide/safe_output.py, the report's output guard and atomic write: every place
that is not a new or a regular file is refused with the cause and left as it was, a symbolic
link to a regular file is followed, permissions follow the umask, and a failed write leaves
neither a temporary file nor a changed target. Run by ctest (label unit) with pytest."""
import errno
import os
import stat
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python", "collide"))
import safe_output  # noqa: E402
from safe_output import OutputPathError  # noqa: E402


def temporaries(folder):
    return [n for n in os.listdir(folder) if ".tmp-" in n]


def refused(path, cause):
    with pytest.raises(OutputPathError) as e:
        safe_output.write_text(path, "new")
    message = str(e.value)
    assert f"'{path}'" in message, message
    assert cause in message, message
    folder = os.path.dirname(path)
    if os.path.isdir(folder):
        assert temporaries(folder) == []
    return message


def test_writes_a_new_file_with_the_umasks_permissions(tmp_path):
    for umask, mode in ((0o022, 0o644), (0o077, 0o600)):
        old = os.umask(umask)
        try:
            path = tmp_path / f"out-{umask:o}.html"
            safe_output.write_text(path, "<p>é</p>")
        finally:
            os.umask(old)
        assert path.read_text(encoding="utf-8") == "<p>é</p>"
        assert stat.S_IMODE(path.stat().st_mode) == mode
    assert temporaries(tmp_path) == []


def test_replaces_a_regular_file(tmp_path):
    path = tmp_path / "summary.md"
    path.write_text("old")
    safe_output.write_bytes(path, b"new")
    assert path.read_bytes() == b"new"


def test_follows_a_link_to_a_regular_file_and_keeps_the_link(tmp_path):
    real, link = tmp_path / "real.md", tmp_path / "link.md"
    real.write_text("old")
    link.symlink_to(real)
    safe_output.write_text(link, "new")
    assert link.is_symlink()
    assert real.read_text() == "new"


def test_refuses_a_fifo_and_leaves_it(tmp_path):
    path = str(tmp_path / "index.html")
    os.mkfifo(path)
    refused(path, "not a regular file (a FIFO)")
    assert stat.S_ISFIFO(os.lstat(path).st_mode)


def test_refuses_a_character_device_and_leaves_it(tmp_path):
    path = str(tmp_path / "index.html")
    try:
        os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, 3))  # a twin of /dev/null, never the real one
    except PermissionError as e:
        pytest.skip(f"cannot make a character device here ({e.strerror}; it needs root or CAP_MKNOD)")
    refused(path, "not a regular file (a character device)")
    assert stat.S_ISCHR(os.lstat(path).st_mode)


def test_refuses_a_link_to_nothing(tmp_path):
    path = str(tmp_path / "index.html")
    os.symlink("nowhere", path)
    refused(path, "a symbolic link to nothing ('nowhere' does not exist)")
    assert os.path.islink(path) and not os.path.exists(tmp_path / "nowhere")


def test_refuses_a_loop_of_links(tmp_path):
    path = str(tmp_path / "index.html")
    os.symlink("index.html", path)
    refused(path, "a loop of symbolic links")
    assert os.path.islink(path)


def test_refuses_a_directory(tmp_path):
    path = str(tmp_path / "index.html")
    os.mkdir(path)
    refused(path, "a directory of that name exists")


def test_names_a_missing_directory(tmp_path):
    path = str(tmp_path / "no" / "such" / "index.html")
    refused(path, f"directory '{tmp_path / 'no' / 'such'}' does not exist")
    assert not os.path.exists(tmp_path / "no")


def test_names_a_path_too_long_as_too_long_not_missing(tmp_path):
    long_name = str(tmp_path / ("n" * 300 + ".md"))
    assert "does not exist" not in refused(long_name, os.strerror(errno.ENAMETOOLONG))
    deep = os.path.join(str(tmp_path), *(["d" * 200] * 24), "index.html")
    assert "does not exist" not in refused(deep, "the path is too long")
    assert os.listdir(tmp_path) == []


def test_names_a_file_in_the_way_of_the_directory(tmp_path):
    (tmp_path / "file").write_text("x")
    refused(str(tmp_path / "file" / "index.html"), "is not a directory (it is a regular file)")


def test_a_failed_rename_leaves_the_target_and_no_temporary(tmp_path, monkeypatch):
    path = tmp_path / "summary.md"
    path.write_text("old")

    def no_space(*args):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "replace", no_space)
    with pytest.raises(OutputPathError, match="No space left on device"):
        safe_output.write_text(path, "new")
    assert path.read_text() == "old"
    assert temporaries(tmp_path) == []


def test_output_directory_refusals(tmp_path):
    fifo = str(tmp_path / "fifo")
    os.mkfifo(fifo)
    with pytest.raises(OutputPathError, match=r"not a directory \(it is a FIFO\)"):
        safe_output.check_output_directory(fifo)
    dangling = str(tmp_path / "dangling")
    os.symlink("nowhere", dangling)
    with pytest.raises(OutputPathError, match="symbolic link to nothing"):
        safe_output.check_output_directory(dangling)
    loop = str(tmp_path / "loop")
    os.symlink("loop", loop)
    with pytest.raises(OutputPathError, match="loop of symbolic links"):
        safe_output.check_output_directory(loop)
    safe_output.make_output_directory(str(tmp_path / "new" / "report"))  # created with its parents
    assert os.path.isdir(tmp_path / "new" / "report")


def test_the_report_refuses_a_fifo_before_reading_anything(tmp_path):
    """make_report.render checks its four files first: a FIFO named index.html is refused (an
    open() for writing would wait for a reader forever), even without any results."""
    make_report = pytest.importorskip("make_report", reason="the report needs matplotlib, numpy and h5py")
    os.makedirs(tmp_path / "report")
    fifo = str(tmp_path / "report" / "index.html")
    os.mkfifo(fifo)
    with pytest.raises(OutputPathError, match="a FIFO"):
        make_report.render(str(tmp_path))
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
