"""The continuation's demonstration blocks as a user loads them: 1060 (set up,
z up, a 4-inch square and a 2-inch-radius circle by via points, on the
printed servo; the circle by Path.Run, then by Spline.Run) and 1062 (pick and
place: over A, down, grasp, up and over to B in one path, release), with and
without a part: the plant's part is placed at A and found at B."""


def counters(r):
    return [v["counter"] for v in r.plant().values()]


def test_shapes_then_pick_and_place(boot):
    r = boot(trace=False)
    r.send("1000 LOAD 1040 LOAD")
    assert r.send("1060 LOAD", timeout=60) == ""
    x, y, z, _ = counters(r)
    assert abs(x) <= 40 and abs(y) <= 40 and abs(z - 400) <= 40     # back at 0 0 Plane
    # a 1-inch part at A (800 800, z 400): picked, carried, left at B
    r.simh("set plant gripper object=1,partx=800,party=800,partz=400")
    assert r.send("1062 LOAD").strip() == "holding"
    x, y, z, _ = counters(r)
    assert abs(x - 3200) <= 40 and abs(y - 2400) <= 40 and abs(z - 1600) <= 40
    g = r.gripper()
    assert g["opening"] == 2.0 and g["contact"] == 0                  # released
    assert max(abs(a - b) for a, b in zip(g["part"], (3200, 2400, 400))) <= 40
    # again: nothing is at A now, the part stays at B
    assert r.send("1062 LOAD").strip() == "nothing held"
    assert r.gripper()["part"] == g["part"]
