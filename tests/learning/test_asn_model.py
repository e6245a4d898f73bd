"""The ASN's Python model (harness/analysis/asn_model.py) alone: FORTH's
arithmetic, the parameters read from block 1070, the transcript parser."""
import pytest

from harness.analysis import asn_log, asn_model as am


def test_arithmetic_is_forths():
    assert am.quot(-7, 2) == -3 and am.quot(7, -2) == -3 and am.quot(7, 2) == 3
    assert am.star_slash(-1000, 300, 4096) == -73           # 32-bit product, towards 0
    assert am.cell(40000) == -25536 and am.cell(-40000) == 25536


def test_fields_and_payoff():
    assert am.field(400, 400) == 64 and am.field(0, 400) == 32 and am.field(1300, 400) == 0
    assert am.sense(0, 3200)[:3] == [64, 32, 0] and am.sense(0, 3200)[-1] == 64
    net = am.Asn(am.Params())
    assert net.payoff(1200, 2000) == -800 and net.at_goal(1800, 1400)
    assert not net.at_goal(1801, 1600)


def test_parameters_come_from_block_1070(tmp_path):
    p = am.Params.from_blocks()
    assert (p.step_size, p.rate, p.noise, p.cooling, p.max_steps) == (400, 16, 8192, 10, 100)
    (tmp_path / "1070.txt").write_text("( nothing )\n400 VAR Step.Size\n")
    with pytest.raises(ValueError, match="defines no Arena"):
        am.Params.from_blocks(tmp_path)


def test_learning_moves_the_acting_element_up_the_others_down():
    p = am.Params.from_blocks()
    net = am.Asn(p)
    net.start_trial()
    assert net.step(0, 0) is not None           # the first step only acts
    act = net.act
    net.step(*net.target(act, (0, 0)))          # the ideal move: r = +-400
    moved = [row[0] for row in net.weights]
    # +x, +y approach the goal from 0 0: r = 400; -x, -y bump: r = 0 - 400
    d = am.star_slash(64 * p.rate, 400 if act in (0, 2) else -400, 16384)
    assert d != 0 and moved[act] == 3 * d
    assert all(w == -d for j, w in enumerate(moved) if j != act)


def test_parser_refuses_a_summary_that_disagrees():
    with pytest.raises(asn_log.LogError, match="3 steps said"):
        asn_log.parse("S 0 0 1\nS 5 5\nT 1 3 0 -3190\n")
    trials = asn_log.parse("S 0 0 1\nS -400 3 \nT 1 1 0 -3597  ok\n")
    assert trials[0].n_steps == 1 and trials[0].path == [(0, 0), (-400, 3)]
