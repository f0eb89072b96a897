"""The house rules, checked on the code: physics never imports the application layer, no module
imports another that imports it back, and an effect plugs in through its adapter alone."""

import ast
import dataclasses
from pathlib import Path

import jax
import numpy as np
import pytest

from diffbearing import build_model, load_scene, run_model
from diffbearing.app import registry
from diffbearing.app.registry import Adapter, Block, Key, Output
from diffbearing.app.stored_models import compile_stored

PACKAGE = Path(__file__).resolve().parents[1] / "diffbearing"


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path) -> set[str]:
    """diffbearing modules `path` imports, at module level or inside functions."""
    name = _module_name(path)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names if alias.name.startswith("diffbearing")}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[:len(base) - node.level + 1]
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            if not module.startswith("diffbearing"):
                continue
            for alias in node.names:  # `from . import adapters` names a module
                candidate = f"{module}.{alias.name}"
                found.add(candidate if _path_of(candidate) else module)
    return {module for module in found if _path_of(module)}


def _path_of(module: str) -> Path | None:
    relative = Path(*module.split("."))
    for path in (PACKAGE.parent / relative.with_suffix(".py"), PACKAGE.parent / relative / "__init__.py"):
        if path.is_file():
            return path
    return None


GRAPH = {_module_name(path): _imports(path) for path in PACKAGE.rglob("*.py")}


def test_physics_never_imports_the_application_layer():
    physics = [name for name in GRAPH if not name.startswith("diffbearing.app") and name != "diffbearing"]
    assert len(physics) > 20
    upward = {name: sorted(m for m in GRAPH[name] if m.startswith("diffbearing.app") or m == "diffbearing")
              for name in physics}
    assert {name: found for name, found in upward.items() if found} == {}


def test_no_import_cycles():
    """Depth-first search over the import graph (the package facade `diffbearing/__init__.py`,
    which re-exports both layers, left out: it is imported by nothing inside)."""
    graph = {name: {m for m in imports if m != "diffbearing"} for name, imports in GRAPH.items() if name != "diffbearing"}
    assert not any("diffbearing" == m for name, imports in GRAPH.items() if name != "diffbearing" for m in imports)
    state: dict[str, str] = {}

    def visit(name, path):
        state[name] = "open"
        for following in sorted(graph.get(name, ())):
            if state.get(following) == "open":
                pytest.fail("import cycle: " + " → ".join(path[path.index(following):] + [following]))
            if following not in state:
                visit(following, path + [following])
        state[name] = "done"

    for name in sorted(graph):
        if name not in state:
            visit(name, [name])


def test_the_graph_holds_function_level_imports():
    """A cycle hidden by an import inside a function is still seen: the CLI imports the model inside
    `main`, the schema imports the adapters package with `from . import adapters`."""
    assert "diffbearing.app.model" in GRAPH["diffbearing.app.cli"]
    assert "diffbearing.app.adapters" in GRAPH["diffbearing.app.schema"]
    assert {"diffbearing.contact.elliptic", "diffbearing.numerics"} <= GRAPH["diffbearing.contact.hertz"]


TOY = Adapter(
    name="toy",
    bearing_types=("tapered_roller",),
    keys={"effects.toy": Key("boolean"), "toy.factor": Key("number", doc="a toy key")},
    blocks=(Block(name="toy", bearing_types=("tapered_roller",), enabled_by=("toy", True), requires=("roller_geometry",),
                  inputs=("bearing", "operating"), outputs=(Output("toy.doubled_load", "N", "kN", "twice the load"),),
                  compute=lambda inputs, settings, results: {"toy.doubled_load": 2.0 * inputs["operating"].load}),),
)


@pytest.fixture
def toy_registered():
    registry.register(TOY)
    yield TOY
    registry.unregister("toy")


def test_a_toy_effect_needs_only_its_adapter(toy_registered):
    """An adapter registered in a test adds its key to the schema, its block to the model and its
    output to the run and the report; nothing else is touched."""
    from diffbearing.app.report import format_report

    scene = load_scene("tapered_roller", ["effects.toy=true"])
    model = build_model(scene)
    assert [block.name for block in model.blocks] == ["roller_geometry", "roller_contact_influence", "toy"]
    result = run_model(model)
    assert float(result.values["toy.doubled_load"]) == pytest.approx(2000.0, rel=1e-14)  # the scene's 1 kN
    assert "twice the load" in format_report(result)


def test_a_block_compiled_apart_gives_the_one_programs_values(toy_registered, monkeypatch):
    """A block with `own_program` is compiled as a program of its own, with the XLA options it
    asks for (the others with XLA's quick settings on the CPU), fed the earlier programs' results;
    the values are those of all blocks in one program."""
    apart = dataclasses.replace(TOY.blocks[0], own_program=True,
                                compiler_options=lambda settings: {"xla_cpu_use_fusion_emitters": False})
    monkeypatch.setitem(registry.ADAPTERS, "toy", dataclasses.replace(TOY, blocks=(apart,)))
    asked = []

    def recording(function, inputs, key, compiler_options=None, release=False):
        asked.append(compiler_options)
        return compile_stored(function, inputs, key, compiler_options, release)

    monkeypatch.setattr(registry, "compile_stored", recording)
    monkeypatch.setattr(registry, "_COMPILED", {})  # not the toy compiled by an earlier test
    model = build_model(load_scene("tapered_roller", ["effects.toy=true"]))
    assert [[block.name for block in group] for group in registry.programs(model.blocks)] == [
        ["roller_geometry", "roller_contact_influence"], ["toy"]]
    result = run_model(model)
    quick = registry.QUICK_COMPILE if jax.default_backend() == "cpu" else {}
    assert asked == [quick, {"xla_cpu_use_fusion_emitters": False}]
    together = jax.jit(registry.evaluate(model.blocks, model.settings))(model.inputs)
    assert set(result.values) == set(together)
    for key, value in together.items():
        assert np.array_equal(result.values[key], np.asarray(value)), key


def test_a_toy_key_nothing_reads_is_refused(toy_registered):
    scene = load_scene("tapered_roller", ["toy.factor=3.0"])
    with pytest.raises(ValueError, match="'toy.factor' not read"):
        build_model(scene)


def test_unregistered_effect_is_unknown():
    with pytest.raises(ValueError, match="unknown key 'effects.toy'"):
        load_scene("tapered_roller", ["effects.toy=true"])


def test_adapters_declare_distinct_blocks_and_consistent_keys():
    names = [block.name for adapter in registry.ADAPTERS.values() for block in adapter.blocks]
    assert len(names) == len(set(names))
    clash = dataclasses.replace(TOY, name="clash", blocks=(), keys={"contact.load": Key("number")})
    with pytest.raises(ValueError, match="declared twice with different meanings"):
        registry.register(clash)


def test_ruff_is_clean():
    """The linter's rules (pyproject.toml, [tool.ruff]) hold over the whole repository."""
    import subprocess
    import sys

    checked = subprocess.run([sys.executable, "-m", "ruff", "check", "--output-format", "concise", str(PACKAGE.parent)],
                             capture_output=True, text=True)
    assert checked.returncode == 0, checked.stdout + checked.stderr


BEARING_KINDS = {"deep_groove_ball", "angular_contact_ball", "cylindrical_roller", "tapered_roller"}
KIND_LISTS = {"BALL_BEARING_KINDS", "ROLLER_KINDS"}
# A bearing type's own modules: its physics package and its adapters (and the parameter module
# that defines the ball bearing's kinds); a branch on a type anywhere else is what the seam forbids.
OWN_MODULES = ("diffbearing.bearings.", "diffbearing.app.adapters.bearings.", "diffbearing.params")
# Branches still waiting to move behind the interface (none left: the friction models look their
# rows up by the kind a bearing's `friction_kind` names, in tables; a bearing type's adapter says
# which scene keys its model refuses, `Adapter.refused`). A module listed here must still branch.
PENDING: set[str] = set()


def _type_branches(path: Path) -> list[str]:
    """`isinstance` on a bearing type's class (Ball…, Roller…) and comparisons with a bearing kind
    (`== "deep_groove_ball"`, `in BALL_BEARING_KINDS`) in `path`, as 'line: source'."""
    source = path.read_text()
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "isinstance" and len(node.args) == 2:
            classes = node.args[1].elts if isinstance(node.args[1], ast.Tuple) else [node.args[1]]
            if any(getattr(c, "id", getattr(c, "attr", "")).startswith(("Ball", "Roller")) for c in classes):
                found.append(node)
        elif isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
            if any(isinstance(s, ast.Constant) and s.value in BEARING_KINDS for s in sides) or any(
                    getattr(s, "id", getattr(s, "attr", None)) in KIND_LISTS for s in node.comparators):
                found.append(node)
    return [f"{node.lineno}: {ast.get_source_segment(source, node)}" for node in found]


def test_no_module_branches_on_a_bearing_type_outside_its_own():
    """Shafts, sets and effects see a bearing through its interface (bearings/interface.py): no
    `isinstance` on a type's class and no comparison with a type's kind outside the type's own
    modules — except the modules still listed in PENDING, which must each still hold one (so that
    the list shrinks as they move)."""
    branching = {name: _type_branches(path) for path in PACKAGE.rglob("*.py")
                 if not (name := _module_name(path)).startswith(OWN_MODULES)}
    branching = {name: found for name, found in branching.items() if found}
    assert {name: found for name, found in branching.items() if name not in PENDING} == {}
    assert set(branching) == PENDING  # a module moved behind the interface leaves the list


def test_the_branch_finder_sees_both_kinds_of_branch(tmp_path):
    probe = tmp_path / "probe.py"
    probe.write_text("def f(s, k):\n    if isinstance(s, BallSupport):\n        return 1\n"
                     "    return k.kind == 'tapered_roller' or k in ROLLER_KINDS\n")
    assert [line.split(":")[0] for line in _type_branches(probe)] == ["2", "4", "4"]
