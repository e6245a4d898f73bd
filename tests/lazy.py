"""A module a test module needs only while its tests run, imported then, not when
pytest collects it: each of make test's workers collects every test module, so an
import at the top (numpy, aiohttp: a tenth of a second or more each) is paid by
every worker, whichever runs the tests; imported at the test, only by the workers
that run one (nothing is saved for a module every worker's tests need anyway).

    controllers_runs = lazy("harness.figures.controllers_runs")
    ...
    controllers_runs.run(...)          # imported here, at the first use
"""
import importlib


class lazy:
    """The module `name`, imported at the first public attribute asked of it. A
    name with a leading _ is not the module's to give: pytest's collection asks each
    object of a test module for its own (_pytestfixturefunction, __test__), and
    must not import it."""

    def __init__(self, name):
        self._name = name

    def __getattr__(self, attr):
        if attr.startswith("_"):
            raise AttributeError(attr)
        return getattr(importlib.import_module(self._name), attr)

    def __repr__(self):
        return f"lazy({self._name!r})"
