"""The lock-step's pure logic alone: build/lockstep_test (tests/controllers/lockstep_test.c)."""
from tests.c_unit import passes


def test_link_and_boundary_unit_tests():
    assert passes("lockstep_test", at_least=20)
