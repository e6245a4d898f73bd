"""The console script format: FORTH lines, comments, directives, bad lines."""
import pytest

from harness.machine.build import fresh_disk
from harness.machine.script import ScriptSyntaxError, Step, parse, read
from harness.machine.script_run import run_steps
from harness.machine.scripted_machine import ScriptError, ScriptedMachine
from tests.run.common import needs_build


def test_lines_comments_and_directives():
    steps = parse("# a comment\n\n1 2 + .\n  #wait 2.5\n#simh show plant\n"
                  "#\n## also a comment\n: X ( -- ) ;   \n", "s")
    assert steps == [Step(3, "forth", "1 2 + ."), Step(4, "wait", "wait 2.5", 2.5),
                     Step(5, "simh", "show plant"), Step(8, "forth", ": X ( -- ) ;")]


@pytest.mark.parametrize("line, message", [
    ("#wiat 2", "s:1: unknown directive #wiat"),
    ("#wait", "s:1: #wait takes simulated seconds"),
    ("#wait -1", "s:1: #wait takes simulated seconds"),
    ("#wait nan", "s:1: #wait takes simulated seconds"),
    ("#simh go", "s:1: #simh takes one of show, set, examine, deposit"),
    ("#simh s cpu", "s:1: #simh takes one of"),
    ("X" * 256, "s:1: line of 256 characters; the FORTH takes at most 255"),
    ("1 \x07 .", "s:1: character '\\x07' cannot be typed"),
])
def test_bad_lines_name_file_and_line(line, message):
    with pytest.raises(ScriptSyntaxError) as caught:
        parse(line, "s")
    assert str(caught.value).startswith(message)


def test_simh_abbreviations_of_permitted_verbs():
    assert [s.text for s in parse("#simh sh plant\n#simh e 100\n#simh dep 100 0", "s")] \
        == ["sh plant", "e 100", "dep 100 0"]


def test_missing_and_binary_scripts(tmp_path):
    with pytest.raises(ScriptSyntaxError, match="cannot read the script"):
        read(tmp_path / "none.script")
    (tmp_path / "b.script").write_bytes(b"1 .\n\xff\n")
    with pytest.raises(ScriptSyntaxError, match="not an ASCII text file"):
        read(tmp_path / "b.script")


@needs_build
def test_a_step_of_unknown_kind_is_refused_before_anything_runs(tmp_path):
    """A Step the parser never makes (kind "shell") is not typed to the FORTH as
    a line: run_steps refuses the list, and the machine has run nothing of it."""
    steps = [Step(1, "forth", "123"), Step(2, "shell", "rm -rf /")]
    with ScriptedMachine(fresh_disk(tmp_path).name, cwd=tmp_path) as m:
        with pytest.raises(ScriptError, match="line 2: a step of kind 'shell'"):
            run_steps(m, steps)
        assert "DEPTH . 0  ok" in m.line("DEPTH .").output   # not even the first step ran
