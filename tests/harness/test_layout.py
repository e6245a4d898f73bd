"""harness/'s packages import one way (harness/README.md): each package only from
packages below it, never sideways or up; no module imports itself round a circle;
every name imported from a harness module exists there. Read from the source with
ast (imports inside functions included), nothing imported."""
import ast
import functools
import gc
import re
from pathlib import Path

import pytest

HARNESS = Path(__file__).resolve().parents[2] / "harness"

# the import order, bottom first; a package may import only packages of a lower rank
RANK = {"blocks": 0, "machine": 1, "analysis": 2, "lab": 2, "controllers": 2,
        "commands": 3, "bench": 4, "fuzz": 4, "soak": 4, "figures": 4, "cli": 4,
        "__main__": 5}


def module_name(path):
    parts = path.relative_to(HARNESS.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def modules():
    return {module_name(p): p for p in sorted(HARNESS.rglob("*.py"))}


@functools.lru_cache(maxsize=None)
def parsed(path):
    """The file's ast: each file is read and parsed once, whichever checks walk it.
    The collector is off while a file is parsed (the new nodes would set off its
    young collections: a third of the parse's CPU), and the trees kept are frozen
    out of its way (they hold no cycles, and its full collections would walk them
    all again and again) until the module's tests are done (forget_the_trees)."""
    text = path.read_text()
    gc.disable()
    try:
        tree = ast.parse(text, str(path))
    finally:
        gc.enable()
    gc.freeze()
    return tree


# the kinds of node the checks look at: imports, string constants, `.parents`,
# and what may hold a docstring
LOOKED_AT = (ast.Import, ast.ImportFrom, ast.Constant, ast.Attribute, ast.Module,
             ast.FunctionDef, ast.ClassDef)


def walk(tree):
    """ast.walk's nodes, in its order (breadth first), from a list that grows as it
    is read: without ast.walk's two generators per node, half the CPU."""
    nodes = [tree]
    for node in nodes:
        for field in node._fields:
            value = getattr(node, field, None)
            if isinstance(value, list):
                nodes += [item for item in value if isinstance(item, ast.AST)]
            elif isinstance(value, ast.AST):
                nodes.append(value)
    return nodes


@functools.lru_cache(maxsize=None)
def looked_at(tree):
    """The nodes of `tree` of the LOOKED_AT kinds, in ast.walk's order: each tree
    is walked once, whichever checks look at it (a walk costs as much as the
    checks that follow it)."""
    return [node for node in walk(tree) if isinstance(node, LOOKED_AT)]


@pytest.fixture(scope="module", autouse=True)
def forget_the_trees():
    yield
    for cached in (parsed, looked_at, graph):
        cached.cache_clear()
    gc.unfreeze()


def imported(path, known):
    """The harness modules (or packages) that the file at path imports."""
    name = module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in looked_at(parsed(path)):
        if isinstance(node, ast.Import):
            found |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[:len(package.split(".")) - node.level + 1]
                base = ".".join(anchor + ([base] if base else []))
            found.add(base)
            found |= {f"{base}.{a.name}" for a in node.names if f"{base}.{a.name}" in known}
    return {m for m in found if m in known and m != name}


@functools.lru_cache(maxsize=None)
def graph():
    """module -> the harness modules it imports (made once for the module's tests;
    read, never changed)."""
    known = modules()
    edges = {name: imported(path, known) for name, path in known.items()}
    # cli imports each subcommand's module by name (importlib), unseen by ast
    edges["harness.cli"] |= {m for m in known if m.startswith("harness.commands.")}
    return edges


def package_of(module):
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def test_every_module_sits_in_a_ranked_package():
    loose = [m for m in modules() if m != "harness" and package_of(m) not in RANK]
    assert not loose, (f"{loose}: put each in a package of harness/README.md's table "
                       "(and RANK here) or add its package there")


def against_order(edges):
    """The imports of another package of the same or a higher rank."""
    return [f"{m} imports {d}" for m, deps in edges.items() for d in deps
            if package_of(d) and package_of(m) and package_of(d) != package_of(m)
            and RANK[package_of(d)] >= RANK[package_of(m)]]


def test_packages_import_only_downwards():
    wrong = against_order(graph())
    assert not wrong, "imports against the order of harness/README.md:\n" + "\n".join(wrong)


def circle_through(edges):
    """One import circle as a list of modules, or [] if there is none."""
    state, stack = {}, []

    def visit(m):
        state[m] = "open"
        stack.append(m)
        for d in sorted(edges.get(m, ())):
            if state.get(d) == "open":
                return stack[stack.index(d):] + [d]
            if d not in state and (found := visit(d)):
                return found
        state[m] = "done"
        stack.pop()
        return []

    for m in sorted(edges):
        if m not in state and (found := visit(m)):
            return found
    return []


def test_no_module_imports_itself_round_a_circle():
    circle = circle_through(graph())
    assert not circle, "import circle: " + " -> ".join(circle)


def top_level_names(tree):
    """The names a module defines at its top level (if/try/with blocks included)."""
    names, todo = set(), list(tree.body)
    while todo:
        node = todo.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            names |= {(a.asname or a.name).split(".")[0] for a in node.names}
        elif isinstance(node, (ast.Assign, ast.AnnAssign, ast.AugAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names |= {n.id for t in targets for n in ast.walk(t) if isinstance(n, ast.Name)}
        for field in ("body", "orelse", "finalbody", "handlers"):
            if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                todo += getattr(node, field, [])
    return names


def missing_names(files):
    """`from harness.X import name` in files where X defines no name and has no
    submodule name."""
    known = modules()
    defined = {m: top_level_names(parsed(p)) for m, p in known.items()}
    wrong = []
    for path in files:
        for node in looked_at(parsed(path)):
            if isinstance(node, ast.ImportFrom) and not node.level and node.module in known:
                wrong += [f"{path}:{node.lineno}: {node.module} has no {a.name}"
                          for a in node.names if a.name not in defined[node.module]
                          and f"{node.module}.{a.name}" not in known]
    return wrong


def test_every_name_imported_from_the_harness_exists():
    """What a move can leave behind unseen until the module runs (make bench-continuation
    imported setup_script from where it no longer was)."""
    tests = Path(__file__).resolve().parents[1]
    wrong = missing_names(sorted(HARNESS.rglob("*.py")) + sorted(tests.rglob("*.py")))
    assert not wrong, "\n".join(wrong)


def test_the_checks_see_a_circle_an_upward_import_and_a_stale_name(tmp_path):
    """The checks themselves: a made-up circle is found, and the old one's shape
    (cli -> commands.regress -> regression -> cli) would be; an import up or
    sideways is named, one down is not; a name a module lacks is named."""
    old = {"harness.cli": {"harness.commands.regress"},
           "harness.commands.regress": {"harness.commands.regression"},
           "harness.commands.regression": {"harness.cli"}}
    assert circle_through(old) == ["harness.cli", "harness.commands.regress",
                                   "harness.commands.regression", "harness.cli"]
    assert against_order(old) == ["harness.commands.regression imports harness.cli"]
    assert circle_through({"a": {"b"}, "b": set()}) == []
    assert against_order({"harness.machine.robot": {"harness.commands.run"},
                          "harness.lab.server": {"harness.analysis.trace"},
                          "harness.commands.run": {"harness.machine.simh"}}) == [
        "harness.machine.robot imports harness.commands.run",
        "harness.lab.server imports harness.analysis.trace"]
    edges = graph()
    assert "harness.machine.build" in edges["harness.machine.robot"]    # the parser sees imports
    assert "harness.machine.script_run" in edges["harness.analysis.regression"]
    stale = tmp_path / "stale.py"
    stale.write_text("from harness.machine.robot import Robot, no_such_name\n")
    assert missing_names([stale]) == [f"{stale}:1: harness.machine.robot has no no_such_name"]


# Each fact of the build and the machine has one home (issue 17): the name is
# assigned there and only imported elsewhere.
FACT_HOMES = {
    "harness.machine.build": ("ROOT", "BUILD", "PDP11", "PDP11_STOCK", "MACHINE_INI", "KERNEL",
                              "KERNEL_MAP", "PRISTINE_DISK", "WORKING_DISK", "RATE"),
    "harness.machine.kernel_layout": ("BODY", "SMUDGE", "LENGTH", "CHAINS"),
    "harness.machine.plant_rows": ("AXES", "COLUMNS", "AXIS_COLUMNS", "GRIPPER_COLUMNS"),
}
# ... and the literals that spell those facts appear only in their home (as a
# value: a path or a name; prose that mentions them, a help text, is not counted)
FACT_LITERALS = {"robot.dsk": "harness.machine.build", "XYZT": "harness.machine.plant_rows",
                 "kernel.lda": "harness.machine.build", "kernel.map": "harness.machine.build"}


def assigned_names(tree):
    """Names a module assigns at its top level (not the ones it imports)."""
    return {n.id for node in tree.body if isinstance(node, (ast.Assign, ast.AnnAssign))
            for t in (node.targets if isinstance(node, ast.Assign) else [node.target])
            for n in ast.walk(t) if isinstance(n, ast.Name)}


def facts_away_from_home(trees):
    """`module: NAME` for each fact assigned, `module: 'literal'` for each fact's
    literal in code, and `module: root from __file__` outside the fact's home.
    trees: module name -> its parsed source."""
    home_of = {name: home for home, names in FACT_HOMES.items() for name in names}
    wrong = []
    for module, tree in sorted(trees.items()):
        wrong += [f"{module}: {n}" for n in sorted(assigned_names(tree))
                  if home_of.get(n, module) != module]
        nodes = looked_at(tree)
        docstrings = {id(node.body[0].value) for node in nodes
                      if isinstance(node, (ast.Module, ast.FunctionDef, ast.ClassDef))
                      and node.body and isinstance(node.body[0], ast.Expr)}
        for node in nodes:
            if isinstance(node, ast.Constant) and isinstance(node.value, str) \
                    and id(node) not in docstrings and not any(c.isspace() for c in node.value):
                wrong += [f"{module}: {lit!r}" for lit, home in FACT_LITERALS.items()
                          if lit in node.value and home != module]
            if isinstance(node, ast.Attribute) and node.attr == "parents" \
                    and module != "harness.machine.build":
                wrong.append(f"{module}: root from __file__")
    return wrong


def test_each_fact_has_one_home():
    wrong = facts_away_from_home({m: parsed(p) for m, p in modules().items()})
    assert not wrong, ("facts defined away from their home (import them from "
                       "harness.machine.build, kernel_layout or plant_rows):\n" + "\n".join(wrong))


def test_the_fact_check_sees_a_copy():
    assert facts_away_from_home({"harness.lab.x": ast.parse(
        'RATE = 300_000\nD = "build/robot.dsk"\nR = Path(__file__).resolve().parents[2]\n')}) == [
        "harness.lab.x: RATE", "harness.lab.x: 'robot.dsk'", "harness.lab.x: root from __file__"]
    assert facts_away_from_home({"harness.lab.x": ast.parse(
        '"""from build/robot.dsk"""\nfrom harness.machine.build import RATE\n'
        'HELP = "default: build/robot.dsk"\n')}) == []


def test_every_package_has_its_line_in_the_readme():
    """harness/README.md's table names each ranked package, and only those."""
    table = (HARNESS / "README.md").read_text()
    named = {m.group(1) for m in re.finditer(r"^\| \d \| `(\w+)(?:/|\.py)`", table, re.M)}
    assert named == set(RANK), sorted(named ^ set(RANK))


DEVICE_KINDS = ("bus", "plant", "lab", "simh", "lockstep")    # pdp11-devices/, one folder per kind


def test_the_devices_are_sorted_by_kind():
    """pdp11-devices/ holds its kinds' folders, the shared header and the machine's
    configuration; every C file is in a kind's folder, which mk/devices.mk builds."""
    devices = HARNESS.parent / "pdp11-devices"
    top = sorted(p.name for p in devices.iterdir())
    assert top == sorted(DEVICE_KINDS + ("devices.h", "machine.ini")), top
    assert all(p.parent.name in DEVICE_KINDS for p in devices.rglob("*.[ch]")
               if p.name != "devices.h")
    kinds = re.search(r"^DEV_KINDS\s*:=\s*(.*)$", (HARNESS.parent / "mk" / "devices.mk")
                      .read_text(), re.M).group(1).split()
    assert tuple(kinds) == DEVICE_KINDS
