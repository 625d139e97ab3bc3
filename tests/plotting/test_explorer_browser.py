"""The explorer in a real browser: headless Chromium (Debian's ``chromium`` and
``chromium-driver``, which .ci/run installs) driven by selenium through the system's
/usr/bin/chromedriver (selenium never downloads a driver here). The page opens from a
file without a console error, draws the traces it should, and a click on a front's
point draws that member's posture (the FK of its joint vector) and lists its joints.
Without selenium or the browser every test skips, saying which is missing."""

import base64
import io
import os
import shutil
import time
from pathlib import Path

import numpy as np
import pytest

from moik import get_robot
from moik.plotting import write_explorer
from moik.plotting.explorer import CurvePanel, Front, FrontPanel, TablePanel

CHROMIUM, CHROMEDRIVER = Path("/usr/bin/chromium"), Path("/usr/bin/chromedriver")

pytest.importorskip("plotly", reason="the explorer needs plotly (the explorer extra)")
webdriver = pytest.importorskip("selenium.webdriver",
                                reason="selenium is not installed (it is in the test extra)")
if not (CHROMIUM.is_file() and CHROMEDRIVER.is_file()):
    pytest.skip(f"no headless Chromium: {CHROMIUM} or {CHROMEDRIVER} is missing (Debian: "
                "apt-get install chromium chromium-driver; .ci/run installs them)",
                allow_module_level=True)

from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402

N_MEMBERS = 9


@pytest.fixture(scope="module")
def driver():
    with pytest.MonkeyPatch.context() as env:
        env.setenv("SE_OFFLINE", "true")  # selenium-manager, should it run: never a download
        d = _start()
    yield d
    d.quit()


def _start():
    """Chromium through the system's chromedriver: with the driver's path given, selenium
    does not look for (or download) one."""
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--enable-unsafe-swiftshader", "--window-size=1400,1000"):
        options.add_argument(arg)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(executable_path=str(CHROMEDRIVER)), options=options)


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    """A page with two fronts (the second without postures, hidden) and an obstacle, curves
    and a table."""
    robot = get_robot("panda")
    X = robot.random_q(N_MEMBERS, rng=np.random.default_rng(7))
    X[0, 3] = robot.upper[3]  # at a limit, not beyond it
    F = np.column_stack([np.linspace(0.1, 1.0, N_MEMBERS), 1.0 / np.linspace(1, 4, N_MEMBERS)])
    target = robot.fk(X[0])
    panels = [
        FrontPanel("fronts", [Front("alg run 0", F, X, group="alg"),
                              Front("alg run 1", F * 1.2, None, group="alg", visible=False)],
                   ["position error (m)", "orientation error (rad)"], robot=robot,
                   target=target, obstacles=[{"type": "mesh3d", "name": "obstacle",
                                              "x": [0.3, 0.5, 0.3, 0.3], "y": [0, 0, 0.2, 0],
                                              "z": [0, 0, 0, 0.2], "opacity": 0.4,
                                              "i": [0, 0, 0, 1], "j": [1, 1, 2, 2],
                                              "k": [2, 3, 3, 3]}]),
        CurvePanel("convergence", {"alg": np.array([[3.0, 2.0, 1.0], [2.0, 1.0, 0.5]])}, "f"),
        TablePanel("statistics", ["algorithm", "HV mean"], [["alg", "0.123"]]),
    ]
    path = write_explorer(tmp_path_factory.mktemp("page") / "explorer.html", panels,
                          title="browser test")
    return {"path": path, "robot": robot, "X": X, "F": F}


@pytest.fixture(scope="module")
def loaded(driver, scene):
    """The page opened once for the tests that only read it (each load takes seconds);
    what the browser logged while it opened. The tests that click reopen it."""
    driver.get_log("browser")  # drop what an earlier page logged
    open_page(driver, scene["path"])
    return driver.get_log("browser")


def open_page(driver, path: Path) -> None:
    driver.get(path.as_uri())
    t0 = time.monotonic()
    while driver.execute_script("return document.body.dataset.ready") != "1":
        if time.monotonic() - t0 > 60:
            raise AssertionError("the page did not finish drawing in 60 s: "
                                 f"{driver.get_log('browser')}")
        time.sleep(0.1)


def links_tip(driver) -> np.ndarray:
    """The last point of the posture view's links trace (the end effector)."""
    xyz = driver.execute_script(
        "const t = document.getElementById('posture-0').data[0];"
        "return [t.x[t.x.length - 1], t.y[t.y.length - 1], t.z[t.z.length - 1]];")
    return np.array(xyz, dtype=float)


def point(driver, trace: int, index: int):
    """The SVG marker of member ``index`` of front ``trace`` (visible traces only)."""
    traces = driver.find_elements(By.CSS_SELECTOR, "#front-0 .scatterlayer .trace")
    return traces[trace].find_elements(By.CSS_SELECTOR, "path.point")[index]


def test_the_page_opens_from_a_file_without_console_errors(driver, loaded):
    assert driver.current_url.startswith("file://")
    severe = [e for e in loaded if e["level"] == "SEVERE"]
    assert not severe
    fetched = driver.execute_script(
        "return performance.getEntriesByType('resource').map(e => e.name)")
    assert not [u for u in fetched if u.startswith(("http:", "https:"))]


def test_it_draws_every_trace(driver, scene, loaded):
    n = driver.execute_script("return ['front-0', 'posture-0', 'figure-1'].map("
                              "i => document.getElementById(i).data.length)")
    # fronts: 2 fronts + the selection ring; posture: links, joints, base, 3 frame-axis
    # traces, the target and its 3 axes, the obstacle; curves: 1 mean curve
    assert n == [3, 11, 1]
    drawn = driver.find_elements(By.CSS_SELECTOR, "#front-0 .scatterlayer .trace")
    assert len(drawn) == 2  # the hidden run is not drawn, the ring is
    assert len(drawn[0].find_elements(By.CSS_SELECTOR, "path.point")) == N_MEMBERS
    assert "0.123" in driver.find_element(By.CSS_SELECTOR, "table.stats").text


def test_the_first_member_is_shown_when_the_page_opens(driver, scene, loaded):
    details = driver.find_element(By.ID, "details-0").text
    assert f"member 1 of {N_MEMBERS}" in details
    assert len(driver.find_elements(By.CSS_SELECTOR, "#details-0 table.joints tr")) == 8
    assert not driver.find_elements(By.CSS_SELECTOR, "#details-0 tr.outside")
    np.testing.assert_allclose(links_tip(driver), scene["robot"].fk(scene["X"][0])[:3, 3],
                               atol=1e-5)


def test_clicking_a_point_shows_that_members_posture_and_joints(driver, scene):
    open_page(driver, scene["path"])
    before = driver.find_element(By.ID, "details-0").text
    k = 5
    ActionChains(driver).move_to_element(point(driver, 0, k)).click().perform()
    details = driver.find_element(By.ID, "details-0").text
    assert details != before and f"member {k + 1} of {N_MEMBERS}" in details
    np.testing.assert_allclose(links_tip(driver), scene["robot"].fk(scene["X"][k])[:3, 3],
                               atol=1e-5)
    q = scene["X"][k]
    assert f"{q[0]:.6g}"[:6] in details  # the joint table lists this member's values
    ring = driver.execute_script("const t = document.getElementById('front-0').data[2];"
                                 "return [t.x[0], t.y[0]];")
    np.testing.assert_allclose(ring, scene["F"][k])


def test_hovering_a_point_shows_its_values(driver, scene, loaded):
    k = 3
    ActionChains(driver).move_to_element(point(driver, 0, k)).perform()
    t0 = time.monotonic()
    text = ""
    while time.monotonic() - t0 < 10 and "member" not in text:
        text = " ".join(e.text for e in driver.find_elements(By.CSS_SELECTOR, ".hovertext"))
        time.sleep(0.1)
    assert f"alg run 0, member {k + 1}" in text  # numbered from 1, as the details
    assert f"{scene['F'][k, 0]:.5g}" in text and "orientation error (rad)" in text


def test_a_legend_click_shows_a_hidden_run_whose_points_have_no_posture(driver, scene):
    open_page(driver, scene["path"])
    items = driver.find_elements(By.CSS_SELECTOR, "#front-0 .legend .traces")
    [hidden] = [i for i in items if i.text == "alg run 1"]
    hidden.click()
    t0 = time.monotonic()
    while len(driver.find_elements(By.CSS_SELECTOR, "#front-0 .scatterlayer .trace")) < 3:
        assert time.monotonic() - t0 < 10, "the hidden run was not drawn after a legend click"
        time.sleep(0.1)
    tip = links_tip(driver)
    ActionChains(driver).move_to_element(point(driver, 1, 2)).click().perform()
    details = driver.find_element(By.ID, "details-0").text
    assert "alg run 1" in details and "no joint vectors stored" in details
    np.testing.assert_array_equal(links_tip(driver), tip)  # the posture view stays


def test_a_screenshot_shows_the_drawn_page(driver, scene, loaded):
    shot = driver.execute_cdp_cmd("Page.captureScreenshot",
                                  {"format": "png", "captureBeyondViewport": True})
    import matplotlib.image

    img = matplotlib.image.imread(io.BytesIO(base64.b64decode(shot["data"])), format="png")
    posture = driver.find_element(By.ID, "posture-0").rect
    y0, x0 = int(posture["y"]), int(posture["x"])
    region = img[y0:y0 + int(posture["height"]), x0:x0 + int(posture["width"]), :3]
    assert region.size and region.std() > 0.02  # the 3-D view holds a drawing, not blank
    out = os.environ.get("MOIK_SCREENSHOTS")
    if out:  # keep the picture to look at
        shutil.os.makedirs(out, exist_ok=True)
        Path(out, "explorer-test.png").write_bytes(base64.b64decode(shot["data"]))


def _body_vertices(shape) -> list[np.ndarray]:
    """A robot shape's vertices in its body's frame: a compound's convex parts' points, a
    box's 8 corners (the fingers' boxes, on the hand)."""
    if hasattr(shape, "parts"):
        return [p.points @ p.pose[:3, :3].T + p.pose[:3, 3] for p in shape.parts]
    h = np.asarray(shape.size) / 2
    corners = np.array([[a, b, c] for a in (-h[0], h[0]) for b in (-h[1], h[1])
                        for c in (-h[2], h[2])])
    return [corners @ shape.pose[:3, :3].T + shape.pose[:3, 3]]


def test_the_arms_collision_geometry_follows_the_selected_posture(driver, tmp_path):
    """The panda's compounds (its URDF meshes' convex parts, what a collision check measures)
    and its fingers' boxes drawn as mesh3d surfaces moved by the shown member's frames: for
    the first member and after selecting another, each body's drawn vertices are its parts'
    at that posture."""
    from moik.plotting.geometry import robot_meshes
    from moik.solver.collision import default_model

    robot = get_robot("panda")
    model = default_model(robot)
    X = robot.random_q(4, rng=np.random.default_rng(11))
    F = np.column_stack([np.linspace(0, 1, 4), np.linspace(1, 0, 4)])
    panel = FrontPanel("fronts", [Front("alg run 0", F, X)], ["a", "b"], robot=robot,
                       robot_shapes=robot_meshes(model))
    path = write_explorer(tmp_path / "shapes.html", [panel], title="collision shapes")
    driver.get_log("browser")
    open_page(driver, path)

    def drawn() -> dict:
        return driver.execute_script(
            "return document.getElementById('posture-0').data.filter(t => t.type === 'mesh3d')"
            ".map(t => [t.name, t.x, t.y, t.z, t.i.length]);")

    for k in (0, 2):
        if k:
            assert driver.execute_script(f"return window.moikExplorer.select(0, 0, {k});")
        frames = robot.frames(X[k])
        shapes = drawn()
        assert [s[0] for s in shapes] == [m["name"] for m in panel.robot_shapes]
        for (_, x, y, z, n_tri), mesh in zip(shapes, panel.robot_shapes, strict=True):
            T = frames[mesh["frame"]]
            local = np.vstack([v for b, s in model.items if b == mesh["frame"]
                               for v in _body_vertices(s)])
            want = local @ T[:3, :3].T + T[:3, 3]
            np.testing.assert_allclose(np.column_stack([x, y, z]), want, atol=2e-5)
            assert n_tri == len(mesh["i"]) > 0
    assert not [e for e in driver.get_log("browser") if e["level"] == "SEVERE"]
