"""The ASN blocks (1070-1078, a reconstruction, docs/learning.md) on the
emulated robot with the printed servo: they load after 1000 LOAD, the Python
model chooses the FORTH's action at each of the first 200 steps and ends
with its weights, the weights survive leaving the FORTH, misuse is refused
with a message, and python -m harness listing lists the blocks. The model's
test and the weights' read one run of the trials (conftest's `learned`,
whose start test_asn_script.py's check reads too).
(test_asn_script.py: the same script gives the same trials.csv; make
asn-runs checks all of a 50-trial run, and the learning itself.)"""
import subprocess
import sys

from harness.analysis import asn_log, asn_model
from harness.machine.robot import Robot
from tests.learning.conftest import MODEL_STEPS


def test_blocks_load_after_the_appendix(disk):
    with Robot(disk=disk, timeout=60) as r:
        assert r.send("1000 LOAD 1070 LOAD") == ""
        ok, out, err = r.reply("Trial")              # no servo yet
        assert not ok and "Set.Up.Robot first" in err
        assert r.send("0 Trials -3 Trials") == ""     # nothing to do, at once


def test_model_chooses_the_same_actions_for_200_steps(learned):
    trials = asn_log.parse(learned.trials)
    net = asn_model.Asn(asn_model.Params.from_blocks())
    forth = asn_log.actions_of(trials)
    compared = [(a, forth[k - 1][n]) for k, n, _, _, a in
                asn_model.replay(net, asn_log.steps_of(trials))]
    assert len(compared) >= MODEL_STEPS
    assert [m for m, _ in compared[:MODEL_STEPS]] == [f for _, f in compared[:MODEL_STEPS]]
    assert [m for m, _ in compared] == [f for _, f in compared]
    done, seed, weights = asn_log.parse_net(learned.net)
    assert (done, seed, weights) == (len(trials), net.seed, net.weights)
    assert any(any(row) for row in weights)                # it learned something


def test_weights_survive_leaving_the_forth(learned):
    """The trials' FORTH has left (`learned`); a new boot on its disk LOADs the net."""
    disk = learned.disk
    before = asn_log.parse_net(learned.net)
    assert before[0] == len(asn_log.parse(learned.trials)) and any(any(row) for row in before[2])
    with open(disk, "rb") as f:                               # block 1079: text, LOADable
        f.seek(1079 * 1024)
        text = f.read(1024).decode("ascii")
    assert text.isprintable() and text.startswith("( ASN net:") and "Net!" in text
    with Robot(disk=disk, timeout=600) as r:                # a new boot, the same disk
        r.send("1000 LOAD 1070 LOAD")
        assert asn_log.parse_net(r.send(".Net")) == before
        r.send("Reset.Net")
        done, seed, weights = asn_log.parse_net(r.send(".Net"))
        assert done == 0 and not any(any(row) for row in weights)


def test_listing_lists_the_blocks():
    done = subprocess.run([sys.executable, "-m", "harness", "listing", "--blocks", "1070-1078"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    for block in range(1070, 1079):
        assert f"Block {block}" in done.stdout
    for word in ("Choose", "Learn", "Act.Move", "Trial", "Trials", ".Net"):
        assert f"header of {word}\n" in done.stdout
