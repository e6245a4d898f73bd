"""The plant physics alone: build/plant_test (tests/devices/plant_test.c)."""
from tests.c_unit import passes


def test_plant_physics_unit_tests():
    assert passes("plant_test", at_least=20)
