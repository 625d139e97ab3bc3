"""Fuzzing what arrives from elsewhere: scene files, capsule-model files, experiment configs,
results folders (lines, ``meta.json``, arrays, symbolic links) and command lines.

Every case must end in a result or a :class:`~moik.exceptions.MoikError` (0 raw
exceptions) within a minute (0 hangs), write or delete nothing outside the folders given,
and ignore no key silently (a file that loads holds only keys its reader knows). Examples are drawn
derandomized (tests/conftest.py), few enough that the module runs in seconds.
"""

import contextlib
import copy
import json
import os
import shutil
import signal
import tempfile
import warnings
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from moik import get_robot
from moik.cli import main
from moik.collision.catalog import collision_model
from moik.collision.io import load_model, load_scene, model_to_dict
from moik.exceptions import MoikError, MoikWarning
from moik.experiments.config import ExperimentConfig, load_config
from moik.experiments.docs import stamp, write_docs
from moik.experiments.explorer import folder_panels
from moik.experiments.headlines import headline
from moik.experiments.report import experiment_section, make_report
from moik.experiments.runner import run_experiment
from moik.experiments.store import ResultStore
from moik.experiments.tables import Results
from tests.experiments.conftest import TINY

# the file formats as moik/collision/io.py documents them (the oracle of "no key ignored")
SHAPE_TYPES = ("box", "capsule", "cylinder", "halfspace", "sphere")
PLACEMENT_KEYS = ("type", "pose", "xyz", "rpy")
SIZE_KEYS = {"sphere": ("radius",), "capsule": ("radius", "length", "a", "b"),
             "cylinder": ("radius", "length"), "box": ("size",),
             "halfspace": ("normal", "offset")}
SCENE_KEYS = ("obstacles", "allowed")
MODEL_KEYS = ("robot", "dof", "links", "shapes", "allowed", "source", "acm")

FUZZ = settings(max_examples=60, deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])

SHAPE_KEYS = sorted({*PLACEMENT_KEYS, *(k for ks in SIZE_KEYS.values() for k in ks), "name",
                     "link", "xzy", "ofset", "radus", "lenght", "Type"})
scalars = st.one_of(st.none(), st.booleans(), st.integers(-10**45, 10**45),
                    st.floats(allow_nan=True, allow_infinity=True), st.text(max_size=12),
                    st.sampled_from([*SHAPE_TYPES, "", "..", "../x", "a\x00b", "x" * 300]))
values = st.recursive(scalars, lambda kids: st.one_of(
    st.lists(kids, max_size=4), st.dictionaries(st.sampled_from(SHAPE_KEYS), kids, max_size=4)),
    max_leaves=12)
numbers = st.one_of(st.floats(-2, 2), st.integers(-3, 3), st.just(10**400 // 10**360),
                    st.floats(allow_nan=True, allow_infinity=True))
vectors = st.one_of(st.lists(numbers, min_size=3, max_size=3), values)


@st.composite
def shapes(draw):
    """A shape description: mostly plausible keys and values, some misspelt or junk."""
    kind = draw(st.one_of(st.sampled_from(SHAPE_TYPES), scalars))
    d = {"type": kind}
    for key in draw(st.lists(st.sampled_from(SHAPE_KEYS), max_size=5, unique=True)):
        d[key] = draw(st.one_of(numbers, vectors, values))
    return d


def _check_keys_known(data, shape_extra):
    """A description that loaded holds only keys its reader knows."""
    for item in data:
        allowed = {*PLACEMENT_KEYS, *SIZE_KEYS[item["type"]], shape_extra}
        assert set(item) <= allowed, sorted(set(item) - allowed)


@contextlib.contextmanager
def _no_hang(seconds: int = 60):
    """Fails the example instead of hanging (SIGALRM; where it is available)."""
    def stop(signum, frame):
        raise AssertionError(f"hung: no result after {seconds} s")

    if not hasattr(signal, "SIGALRM"):
        yield
        return
    before = signal.signal(signal.SIGALRM, stop)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, before)


def _quiet(call, *args, **kwargs):
    """``call(...)``, or None when it raises a MoikError (numpy warnings are errors), within
    a minute (a hang fails the test)."""
    with _no_hang(), warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.simplefilter("ignore", MoikWarning)
        try:
            return call(*args, **kwargs)
        except MoikError:
            return None


@FUZZ
@given(obstacles=st.one_of(st.lists(shapes(), max_size=4), values),
       extra=st.dictionaries(st.sampled_from(["allowed", "alowed", "obstacle", "units"]),
                             values, max_size=2),
       as_file=st.booleans(), cut=st.integers(0, 400))
@example(obstacles=[{"type": "box", "size": [1, 1, 1], "xzy": [1, 0, 0]}], extra={},
         as_file=False, cut=0)
def test_scene_files(obstacles, extra, as_file, cut):
    data = {"obstacles": obstacles, **extra}
    source = data
    with tempfile.TemporaryDirectory() as tmp:
        if as_file:
            text = json.dumps(data)
            path = Path(tmp) / "scene.json"
            path.write_text(text[:cut] if cut and cut < len(text) else text)
            source = path
        scene = _quiet(load_scene, source)
    if scene is not None and not as_file:
        assert set(data) <= set(SCENE_KEYS)
        _check_keys_known(obstacles, "name")


@FUZZ
@given(edits=st.lists(st.tuples(st.sampled_from([*MODEL_KEYS, "shape", "shapes.0", "shapes.1",
                                                 "robot", "acm"]),
                                st.one_of(values, shapes(), st.just(None))), max_size=3))
def test_capsule_model_files(edits):
    robot = get_robot("planar2")
    data = model_to_dict(collision_model(robot))
    for where, value in edits:
        if where.startswith("shapes."):
            k = int(where.split(".")[1])
            if not isinstance(data.get("shapes"), list) or k >= len(data["shapes"]):
                continue
            if isinstance(value, dict) and isinstance(data["shapes"][k], dict):
                data["shapes"][k] = {**data["shapes"][k], **value}
            else:
                data["shapes"][k] = value
        elif value is None:
            data.pop(where, None)
        else:
            data[where] = value
    model = _quiet(load_model, data, robot)
    if model is not None:
        assert set(data) <= set(MODEL_KEYS)
        _check_keys_known(data["shapes"], "link")


CONFIG_KEYS = sorted({*TINY, "iteratons", "quik", "extends", "analyses", "label", "paper"})


@FUZZ
@given(edits=st.lists(st.tuples(st.sampled_from(CONFIG_KEYS), values), max_size=3),
       text=st.one_of(st.none(), st.binary(max_size=200),
                      st.sampled_from([b'extends = "../x"\n', b"x = " + b"[" * 3000 + b"]" * 3000,
                                       b'name = "\xff"\n', b'extends = ["a"]\n'])))
def test_experiment_configs(edits, text):
    cfg = copy.deepcopy(TINY)
    for key, value in edits:
        cfg[key] = value
    config = _quiet(ExperimentConfig.from_dict, cfg)
    if config is not None:
        assert set(cfg) <= set(TINY) | {"extends", "analyses", "paper"}
    if text is not None:
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "mine.toml"
            path.write_bytes(text)
            _quiet(load_config, path)


@pytest.fixture(scope="module")
def stored(tmp_path_factory):
    out = tmp_path_factory.mktemp("stored") / "r"
    run_experiment(ExperimentConfig.from_dict(copy.deepcopy(TINY)), out=out)
    return out


META_KEYS = ["experiment", "experimnt", "extra", "config", "targets", "trials", "sessions",
             "format", "quick", "algorithms", "config_fingerprint", "versions", "machine",
             "git_commit"]
KNOWN_META = set(META_KEYS) - {"experimnt", "extra"}
CONFIG_FIELDS = ["name", "title", "source", "problem", "robot", "runs", "pop_size", "seed",
                 "iterations", "analyses", "algorithms"]
MEMBERS = ["results.jsonl", "arrays", "meta.json", "figures", "report.md", "report.html"]
BAD_LINES = [b"[" * 100_000 + b"]" * 100_000, b"\xff\xfe", b"{}", b'{"trial": "a\\u0000b"}',
             b"1e400", b"-" * 500]
mutations = st.one_of(
    st.tuples(st.just("line"), st.integers(0, 9), st.one_of(
        st.sampled_from(BAD_LINES), values.map(lambda v: json.dumps(v).encode()))),
    st.tuples(st.just("record"), st.integers(0, 7), st.sampled_from(
        ["trial", "status", "algorithm", "target", "run", "best_f", "time", "arrays"]), values),
    st.tuples(st.just("meta"), st.sampled_from(META_KEYS), st.one_of(st.just("<delete>"),
                                                                     values)),
    st.tuples(st.just("config"), st.sampled_from(CONFIG_FIELDS), st.one_of(
        st.just("<delete>"), values)),
    st.tuples(st.just("array"), st.integers(0, 7), st.sampled_from(["empty", "half", "junk"])),
    st.tuples(st.just("link"), st.sampled_from(MEMBERS), st.sampled_from(["file", "folder"])),
)


def _apply(folder: Path, victim: Path, mutation) -> None:
    kind = mutation[0]
    touched = {"line": "results.jsonl", "record": "results.jsonl", "meta": "meta.json",
               "config": "meta.json", "array": "arrays"}.get(kind)
    if touched is not None and (folder / touched).is_symlink():
        return  # already replaced by a link: the link is the change
    if kind in ("line", "record"):
        lines = (folder / "results.jsonl").read_bytes().split(b"\n")[:-1]
        k = mutation[1] % len(lines)
        if kind == "line":
            lines[k] = mutation[2]
        else:
            with contextlib.suppress(ValueError, RecursionError):
                record = json.loads(lines[k])
                if isinstance(record, dict):
                    record[mutation[2]] = mutation[3]
                    lines[k] = json.dumps(record).encode()
        (folder / "results.jsonl").write_bytes(b"\n".join(lines) + b"\n")
    elif kind in ("meta", "config"):
        try:
            meta = json.loads((folder / "meta.json").read_text())
            where = meta if kind == "meta" else meta["config"]
            assert isinstance(where, dict)
        except (AssertionError, ValueError, RecursionError, OSError, KeyError, TypeError):
            return  # meta.json is already replaced by a link or junk
        if mutation[2] == "<delete>":
            where.pop(mutation[1], None)
        else:
            where[mutation[1]] = mutation[2]
        (folder / "meta.json").write_text(json.dumps(meta))
        if kind == "meta" and mutation[1] not in KNOWN_META and mutation[2] != "<delete>":
            assert _quiet(ResultStore.open, folder) is None  # an unknown key is refused
    elif kind == "array":
        files = sorted((folder / "arrays").glob("*.npz"))
        path = files[mutation[1] % len(files)]
        data = path.read_bytes()
        path.write_bytes({"empty": b"", "half": data[: len(data) // 2],
                          "junk": b"PK\x03\x04" + b"\x00" * 64}[mutation[2]])
    else:
        member = folder / mutation[1]
        if member.is_dir() and not member.is_symlink():
            shutil.rmtree(member)
        elif member.exists() or member.is_symlink():
            member.unlink()
        os.symlink(victim / ("dir" if mutation[2] == "folder" else "file.txt"), member)


def _snapshot(root: Path) -> dict:
    return {str(p.relative_to(root)): (p.read_bytes() if p.is_file() and not p.is_symlink()
                                       else None)
            for p in sorted(root.rglob("*"))}


@FUZZ
@given(changes=st.lists(mutations, min_size=1, max_size=3))
@example(changes=[("meta", "experiment", "../../x/y")])
@example(changes=[("link", "results.jsonl", "file")])
@example(changes=[("link", "arrays", "folder")])
def test_results_folders(stored, changes):
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        folder, docs, victim = root / "work" / "r", root / "docs", root / "victim"
        shutil.copytree(stored, folder)
        docs.mkdir()
        (victim / "dir").mkdir(parents=True)
        (victim / "dir" / ".keep.tmp").write_text("keep")
        (victim / "dir" / "keep.png").write_text("keep")
        (victim / "file.txt").write_text("keep\n")
        for change in changes:
            _apply(folder, victim, change)
        outside = _snapshot(victim)
        store = _quiet(ResultStore.open, folder, verify=True)
        if store is not None:
            res = _quiet(Results, store)
            if res is not None:
                _quiet(experiment_section, store, figures=False, link=str)
                _quiet(headline, res)
                _quiet(stamp, store, res, generated_at=None)
                _quiet(folder_panels, store)
        _quiet(make_report, folder, figures=False)
        _quiet(write_docs, [folder], docs, figures=False)
        assert _snapshot(victim) == outside  # 0 writes or deletions outside
        for path in root.rglob("*"):
            assert path == folder.parent or path.is_relative_to(folder) or \
                path.is_relative_to(docs) or path.is_relative_to(victim), path


@settings(FUZZ, max_examples=6)
@given(changes=st.lists(st.tuples(st.just("link"), st.sampled_from(MEMBERS[:3]),
                                  st.sampled_from(["file", "folder"])), min_size=1, max_size=2))
def test_resuming_a_folder_with_links_writes_nothing_outside(stored, changes):
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        folder, victim = root / "work" / "r", root / "victim"
        shutil.copytree(stored, folder)
        (victim / "dir").mkdir(parents=True)
        (victim / "dir" / ".keep.tmp").write_text("keep")
        (victim / "file.txt").write_text("keep\n")
        for change in changes:
            _apply(folder, victim, change)
        outside = _snapshot(victim)
        with contextlib.suppress(MoikError), _no_hang():
            run_experiment(ExperimentConfig.from_dict(copy.deepcopy(TINY)), out=folder,
                           resume=True)
        assert _snapshot(victim) == outside


CLI_WORDS = ["solve", "fk", "report", "robots", "experiment", "run", "planar2", "--target",
             "--n-solutions", "--seed", "--scene", "--config", "--out", "--pareto", "--docs",
             "--tol", "--deg", "--json", "--euler", "--quick", "--limit", "--html", "--plot"]
CLI_VALUES = ["0", "1", "-1", "2.5", "nan", "inf", "1e308", "1000000000", "", "x", "/dev/zero",
              "/dev/null", "missing.json", "joint_motion", "..", "a\tb"]


@FUZZ
@given(argv=st.lists(st.one_of(st.sampled_from(CLI_WORDS), st.sampled_from(CLI_VALUES)),
                     min_size=1, max_size=8))
@example(argv=["solve", "planar2", "--target", "1", "0", "0", "--n-solutions", "1000000000"])
@example(argv=["solve", "planar2", "--target", "1", "0", "0", "--scene", "/dev/zero"])
def test_command_lines(argv, capsys):
    with tempfile.TemporaryDirectory() as tmp:
        cwd = os.getcwd()
        os.chdir(tmp)
        try:
            with _no_hang():
                status = main(argv)
        except SystemExit as exc:  # the parser: one error line, status 2 (or --help: 0)
            status = exc.code
        finally:
            os.chdir(cwd)
        err = capsys.readouterr().err
        assert "Traceback" not in err
        assert status in (0, 1, 2), status
        if status == 2:
            errors = [line for line in err.splitlines() if line.startswith("moik: error: ")]
            assert len(errors) == 1, err
