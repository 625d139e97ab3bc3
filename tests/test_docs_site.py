"""The documentation site (mkdocs.yml): ``mkdocs build --strict`` passes (no broken link or
anchor, no missing page or snippet), the API reference documents every public name of
moik's main packages, every results page is in the navigation, no page sends a reader to
../shared, and every example is in the gallery (tests/test_docs_blocks.py runs them and
checks what they print). Without mkdocs (the ``docs`` extra; also in ``test``) the build
tests skip, saying so."""

import importlib
import inspect
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
EXAMPLES = sorted((DOCS / "examples").glob("*.py"))
API = {"moik": "moik", "moik.problems": "problems", "moik.algorithms": "algorithms",
       "moik.solver": "solver", "moik.metrics": "metrics", "moik.plotting": "plotting",
       "moik.collision": "collision"}


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    for module in ("mkdocs", "mkdocstrings", "material", "mkdocstrings_handlers.python"):
        pytest.importorskip(module, reason=f"{module} is not installed: the site needs the "
                            "'docs' extra (pip install -e '.[docs]')")
    out = tmp_path_factory.mktemp("site")
    run = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "-f",
                          str(ROOT / "mkdocs.yml"), "-d", str(out)], cwd=ROOT,
                         capture_output=True, text=True, timeout=600,
                         env={**os.environ, "NO_MKDOCS_2_WARNING": "1"})
    return out, run


def test_the_site_builds_in_strict_mode(site):
    out, run = site
    assert run.returncode == 0, run.stdout + run.stderr
    assert (out / "index.html").is_file() and (out / "results" / "eosma-table8.html").is_file()


def test_the_site_browses_from_disk(site):
    """Every link between pages names an .html file (use_directory_urls: false), so the
    built site works opened as files, without a web server."""
    out, run = site
    assert run.returncode == 0, run.stdout + run.stderr
    html = (out / "index.html").read_text()
    links = re.findall(r'href="([^"#:]+)"', html)
    pages = [link for link in links if not link.endswith((".css", ".js", ".png", ".svg",
                                                          ".ico", ".xml", ".json"))]
    assert pages and all(link.endswith(".html") for link in pages), pages
    assert (out / "results" / "eosma-table8.html").is_file()


def _documented(package: str, name: str, html: str) -> bool:
    """Rendered under the package's name, or where it is defined (a name shadowed by a
    submodule of the same name, a registry constant), or linked (a subpackage)."""
    obj = getattr(importlib.import_module(package), name)
    if inspect.ismodule(obj):
        return f'href="{obj.__name__.rsplit(".", 1)[-1]}.html' in html
    if name == "__version__":
        return "moik.__version__" in html
    ids = [f"{package}.{name}", f"{package}.registry.{name}"]
    if inspect.isclass(obj) or inspect.isfunction(obj):
        ids.append(f"{obj.__module__}.{name}")
    return any(f'id="{i}"' in html for i in ids)


@pytest.mark.parametrize("package", sorted(API))
def test_the_api_reference_documents_every_public_name(site, package):
    out, run = site
    assert run.returncode == 0, run.stdout + run.stderr
    html = (out / "api" / f"{API[package]}.html").read_text()
    public = importlib.import_module(package).__all__
    missing = [n for n in public if not _documented(package, n, html)]
    assert not missing, (f"docs/api/{API[package]}.md does not document {missing} of "
                         f"{package}.__all__: add a '::: module.name' entry")


def test_every_page_is_in_the_navigation():
    yaml = pytest.importorskip("yaml", reason="pyyaml comes with mkdocs")
    text = (ROOT / "mkdocs.yml").read_text()
    nav = yaml.safe_load(text)["nav"]

    def pages(node):
        if isinstance(node, str):
            yield node
        elif isinstance(node, list):
            for n in node:
                yield from pages(n)
        elif isinstance(node, dict):
            for v in node.values():
                yield from pages(v)

    listed = set(pages(nav))
    on_disk = {p.relative_to(DOCS).as_posix() for p in DOCS.rglob("*.md")
               if "figures" not in p.parts}
    assert on_disk - listed == set()
    assert listed - on_disk == set()


def test_no_page_sends_a_reader_to_shared():
    for page in [*DOCS.rglob("*.md"), ROOT / "mkdocs.yml"]:
        text = page.read_text()
        assert not re.search(r"\.\./shared|\]\(/?shared/|`shared/", text), page


def test_every_example_is_in_the_gallery():
    gallery = (DOCS / "gallery.md").read_text()
    assert len(EXAMPLES) >= 4
    for example in EXAMPLES:
        assert f'--8<-- "examples/{example.name}"' in gallery


TABLE_CHECK = """
return [...document.querySelectorAll('article table')].filter(
  (t) => t.scrollWidth > t.clientWidth + 1 || t.getBoundingClientRect().right >
         document.querySelector('article').getBoundingClientRect().right + 1
).map((t) => t.rows[0].textContent.trim().slice(0, 60));
"""


def test_no_table_is_clipped_at_1280_px(site, monkeypatch):
    """In headless Chromium 1280 px wide, every table of every page fits the page's
    content area whole (docs/stylesheets/extra.css; results pages without a table of
    contents beside them): none is cut off or needs scrolling sideways."""
    chromium, chromedriver = Path("/usr/bin/chromium"), Path("/usr/bin/chromedriver")
    if not (chromium.is_file() and chromedriver.is_file()):
        pytest.skip("no headless Chromium (Debian: apt-get install chromium chromium-driver)")
    webdriver = pytest.importorskip("selenium.webdriver", reason="selenium (test extra)")
    from selenium.webdriver.chrome.service import Service

    out, run = site
    assert run.returncode == 0, run.stdout + run.stderr
    monkeypatch.setenv("SE_OFFLINE", "true")  # selenium-manager never downloads
    options = webdriver.ChromeOptions()
    options.binary_location = str(chromium)
    for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                "--window-size=1280,900"):
        options.add_argument(arg)
    driver = webdriver.Chrome(service=Service(executable_path=str(chromedriver)),
                              options=options)
    try:
        clipped = {}
        pages = sorted(out.glob("*.html")) + sorted((out / "results").glob("*.html"))
        for page in pages:
            driver.get(page.as_uri())
            found = driver.execute_script(TABLE_CHECK)
            if found:
                clipped[page.name] = found
    finally:
        driver.quit()
    assert len(pages) > 30 and clipped == {}
