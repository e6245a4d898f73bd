"""The hand-assembled programs of the harness tests, word by word against SIMH's
disassembler (a wrong branch offset cannot pass unnoticed)."""
from harness.analysis.pdp11prog import check_listing
from servo_program import servo_program
from timing_programs import call_program, counting_handler, mixed_program


def test_every_word_matches_simh_disassembly():
    for prog in (servo_program(), counting_handler(), call_program(), mixed_program()):
        assert check_listing(prog) == []
