"""SET PLANT settings as data, and the coordinator applying them at a boundary:
build/plant_command_test (tests/controllers/plant_command_test.c)."""
from tests.c_unit import passes


def test_plant_settings_and_their_boundary_unit_tests():
    assert passes("plant_command_test", at_least=20)
