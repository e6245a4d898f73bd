"""The continuation's demonstration blocks as a user loads them: 1060 (set up,
z up, a 4-inch square and a 2-inch-radius circle by via points, on the
printed servo; the circle by Path.Run, then by Spline.Run) and 1062 (pick and
place: over A, down, grasp, up and over to B in one path, release), with and
without a part."""


def counters(r):
    return [v["counter"] for v in r.plant().values()]


def test_shapes_then_pick_and_place(boot):
    r = boot(trace=False)
    r.send("1000 LOAD 1040 LOAD")
    assert r.send("1060 LOAD", timeout=60) == ""
    x, y, z, _ = counters(r)
    assert abs(x) <= 40 and abs(y) <= 40 and abs(z - 400) <= 40     # back at 0 0 Plane
    r.simh("set plant gripper object=1")
    assert r.send("1062 LOAD").strip() == "holding"
    x, y, z, _ = counters(r)
    assert abs(x - 3200) <= 40 and abs(y - 2400) <= 40 and abs(z - 1600) <= 40
    assert "opening 2.00 in" in r.simh("show plant")                 # released
    r.simh("set plant gripper object=0")                              # taken away
    assert r.send("1062 LOAD").strip() == "nothing held"
