"""Reading what the simulator says about the plant: SHOW PLANT rows and traces."""
import csv

AXES = "XYZT"
QUIET = "".join(f"set plant {a} walk=0\n" for a in AXES)   # offsets constant


def show_rows(output):
    """The last SHOW PLANT state table as {axis: dict}."""
    rows = {}
    for line in output.splitlines():
        f = line.split()
        if line.startswith("  ") and len(f) == 11 and f[0] in AXES:
            rows[f[0]] = dict(pos=float(f[1]), vel=float(f[4]), dac=int(f[5]),
                              vcmd=float(f[6]), offset=float(f[7]), stop=f[8],
                              run=int(f[9]), counter=int(f[10]))
    return rows


def read_trace(path):
    with open(path, newline="") as f:
        return [dict(t=float(r["time_s"]), axis=r["axis"], dac=int(r["dac"]),
                     vcmd=float(r["vcmd"]), vel=float(r["vel"]), pos=float(r["pos"]),
                     counter=int(r["counter"])) for r in csv.DictReader(f)]
