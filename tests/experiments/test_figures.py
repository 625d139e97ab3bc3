"""The report's figures: units on every axis, the proposed method emphasised."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from moik.experiments.figures import make_figures, objective_label, orientation_unit  # noqa: E402
from moik.experiments.runner import run_experiment  # noqa: E402
from moik.experiments.store import ResultStore  # noqa: E402
from moik.experiments.tables import Results  # noqa: E402


def test_objective_labels_name_formula_and_units():
    assert objective_label({"kind": "position"}, "m") == ("m", "position error (m)")
    units, formula = objective_label({"kind": "pose", "orientation": "eosma-euler",
                                      "weights": [0.5, 0.5]}, "m")
    assert units == "m and rad added"
    assert formula == "0.5 x position error (m) + 0.5 x eosma-euler orientation error (rad)"
    units, formula = objective_label({"kind": "position", "displacement_weight": 1e-15}, "cm")
    assert units == "cm and rad added" and formula.endswith("+ 1e-15 x joint distance (rad)")
    assert objective_label({"kind": "pose", "orientation": "frobenius"}, "mm")[0] == "mm"
    assert orientation_unit("geodesic") == "rad" and orientation_unit("frobenius") == (
        "dimensionless")


def test_figures_carry_units_and_emphasise_the_proposed(tmp_path, tiny_config, monkeypatch):
    out = tmp_path / "r"
    run_experiment(tiny_config, out=out)
    monkeypatch.setattr(plt, "close", lambda *args: None)  # keep the figures to look at them
    try:
        made, notes = make_figures(Results(ResultStore.open(out)), out / "figures")
        axes = [ax for n in plt.get_fignums() for ax in plt.figure(n).axes]
    finally:
        monkeypatch.undo()
        plt.close("all")
    assert notes == [] and {p.name for _, p in made} >= {"convergence.png", "errors.png"}
    by_title = {ax.get_title().split("\n")[0]: ax for ax in axes}
    conv = by_title["Mean convergence"]
    assert conv.get_ylabel().startswith("mean best objective (m)")
    assert conv.get_title() == "Mean convergence\nf = position error (m)"
    bold = [t.get_text() for t in conv.get_legend().get_texts() if t.get_fontweight() == "bold"]
    assert bold == ["eosma (n=4)"]  # the config's proposed algorithm
    assert by_title["Final objective values"].get_ylabel().startswith("final objective (m)")
    assert by_title["Solve time per target"].get_ylabel().endswith("(s)")


def _axes_of_figures(res, folder, monkeypatch):
    monkeypatch.setattr(plt, "close", lambda *args: None)  # keep the figures to look at them
    try:
        made, notes = make_figures(res, folder)
        axes = [ax for n in plt.get_fignums() for ax in plt.figure(n).axes]
    finally:
        monkeypatch.undo()
        plt.close("all")
    return made, notes, axes


def test_one_unit_per_quantity_across_the_figures(tmp_path, monkeypatch):
    """Joint values in degrees in every panel (motion, joint history, path), errors with units."""
    from moik.experiments.registry import get_experiment

    labels = []
    for name in ("eosma-table9", "mpso-circle"):
        out = tmp_path / name
        run_experiment(get_experiment(name), quick=True, out=out)
        made, notes, axes = _axes_of_figures(Results(ResultStore.open(out)), out / "f",
                                             monkeypatch)
        assert notes == [] and made
        labels += [ax.get_ylabel() for ax in axes if ax.get_ylabel()]
    joint = [y for y in labels if y.startswith("joint ")]
    assert {y.split(" (")[1] for y in joint} == {"deg)", "deg/s)", "deg/s²)"}, joint
    assert sum(y == "joint angle (deg)" for y in joint) >= 3  # motion, history, path panels
    errors = [y for y in labels if "error" in y and "objective" not in y]
    assert any(y.startswith("position error (cm)") for y in errors)  # the arm's unit
    assert all("(rad)" in y for y in errors if y.startswith("orientation error")), errors
