"""os.system in decks: the file commands of lang.shell, confined to the
run's output folder."""

import pytest

from asterlite.errors import UnsupportedError
from asterlite.lang import shell


def run(command, folder):
    said = []
    status = shell.run(command, lambda: folder, said.append, 10_000)
    return status, said


def test_cat_and_ls_show_a_file_the_deck_wrote(tmp_path):
    (tmp_path / "fort.38").write_text("line 1\nline 2\n")
    status, said = run("cat fort.38", tmp_path)
    assert status == 0 and said == ["line 1", "line 2"]
    status, said = run("ls -ltr fort.38", tmp_path)
    assert status == 0 and len(said) == 1 and said[0].endswith(" fort.38") and " 14 " in said[0]


def test_failures_give_the_shell_status(tmp_path):
    status, said = run("cat missing", tmp_path)
    assert status == 256 and "No such file" in said[0]
    status, said = run("ls missing", tmp_path)
    assert status == 512


def test_echo_mkdir_and_cp_lay_out_files_inside_the_folder(tmp_path):
    assert run("mkdir datadir", tmp_path)[0] == 0
    assert run("echo data1 > datadir/data1", tmp_path)[0] == 0
    assert run("echo more >> datadir/data1", tmp_path)[0] == 0
    assert (tmp_path / "datadir" / "data1").read_text() == "data1\nmore\n"
    assert run("cp datadir/data1 copy", tmp_path)[0] == 0
    assert (tmp_path / "copy").read_text() == "data1\nmore\n"
    assert run("mkdir datadir", tmp_path)[0] == 256  # exists, as mkdir says
    status, said = run("ls", tmp_path)
    assert said == ["copy", "datadir"]


@pytest.mark.parametrize(
    "command",
    [
        "cp fort.21 /home/someone",
        "cat ../secret",
        "rm fort.38",
        "ls | wc",
        "echo a; rm b",
        "echo $HOME",
        "cat `x`",
        "bash fort.88",
        "ls 2> err",
    ],
)
def test_what_leaves_the_folder_or_is_not_a_file_command_is_refused(tmp_path, command):
    with pytest.raises(UnsupportedError):
        run(command, tmp_path)


def test_a_link_out_of_the_folder_is_refused(tmp_path):
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "f").write_text("x")
    folder = tmp_path / "run"
    folder.mkdir()
    (folder / "link").symlink_to(outside)
    with pytest.raises(UnsupportedError):
        run("cat link/f", folder)


def test_without_an_output_folder_commands_are_validated_only(tmp_path):
    assert shell.run("cat fort.38", lambda: None, print, 100) == 0
    with pytest.raises(UnsupportedError):
        shell.run("rm fort.38", lambda: None, print, 100)
