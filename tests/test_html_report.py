"""The report to hand on (`--report FILE.html`): one self-contained file, parsed — its sections, the
viewport for phones, no external file, script or font, the figure an embedded PNG, the inputs, the
results as the JSON holds them, every warning, the versions and the command — and opened in a
headless browser where the machine has one (this one and CI have none: that test is skipped)."""

import base64
import html.parser
import json
import shutil
import subprocess

import pytest

from diffbearing import __version__
from diffbearing.app import cli
from diffbearing.app.formatting import format_number

from .helpers import example_scene


class _Parsed(html.parser.HTMLParser):
    """Tags with their attributes, the text of each section (by its h2) and of the title."""

    def __init__(self):
        super().__init__()
        self.tags, self.sections, self.text, self._heading, self._in_h2 = [], {}, [], None, False
        self.declarations = []

    def handle_decl(self, decl):
        self.declarations.append(decl)

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        self._in_h2 = tag == "h2"

    def handle_endtag(self, tag):
        self._in_h2 = False if tag == "h2" else self._in_h2

    def handle_data(self, data):
        self.text.append(data)
        if self._in_h2:
            self._heading = data
            self.sections[data] = []
        elif self._heading is not None:
            self.sections[self._heading].append(data)


def _report(capsys, tmp_path, *arguments):
    page, document = tmp_path / "report.html", tmp_path / "out.json"
    code = cli.main(["run", *arguments, "--report", str(page), "--json", str(document)])
    out = capsys.readouterr().out
    parsed = _Parsed()
    parsed.feed(page.read_text(encoding="utf-8"))
    return code, out, page.read_text(encoding="utf-8"), parsed, json.loads(document.read_text())


def test_the_report_is_one_self_contained_file_of_the_run(capsys, tmp_path):
    """gearbox_duty_cycle: exit 0; a doctype, UTF-8, the viewport; its sections; nothing loaded from
    outside (no script, link, external src); the figure a PNG in the page; each input key; the
    cycle's L10 as the JSON holds it; the version and the command."""
    code, out, text, parsed, document = _report(capsys, tmp_path, "gearbox_duty_cycle")
    assert code == 0 and "report written to" in out
    assert parsed.declarations == ["DOCTYPE html"]
    metas = [attrs for tag, attrs in parsed.tags if tag == "meta"]
    assert {"charset": "utf-8"} in metas and any(attrs.get("name") == "viewport" for attrs in metas)
    assert set(parsed.sections) >= {"Errors and warnings (envelope checks)", "Inputs", "Results", "Figure",
                                    "Report as printed"}
    assert not any(tag in ("script", "link", "iframe") for tag, _ in parsed.tags)
    sources = [attrs["src"] for tag, attrs in parsed.tags if "src" in attrs]
    assert len(sources) == 1 and sources[0].startswith("data:image/png;base64,")
    assert base64.b64decode(sources[0].split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
    inputs = "".join(parsed.sections["Inputs"])
    for key in ("bearing.ball_diameter", "operating.force", "lubricant.cleanliness", "life.reliability"):
        assert key in inputs
    results = "".join(parsed.sections["Results"])
    assert "duty.life.L10" in results and format_number(document["duty"]["life"]["L10"]) in results
    assert f"diffbearing {__version__}" in text and "diffbearing run gearbox_duty_cycle --report" in text


def test_every_warning_of_the_run_is_in_the_report(capsys, tmp_path):
    """deep_groove_6411 under 100 kN (a contact past ISO 76's 4 200 MPa): the report lists each of the
    run's warnings, as the JSON holds them."""
    code, _, _, parsed, document = _report(capsys, tmp_path, example_scene("deep_groove_6411"), "--set",
                                           'operating.force=["100 kN", "0 N", "0 N"]')
    assert code == 0 and document["warnings"]
    checks = "".join(parsed.sections["Errors and warnings (envelope checks)"])
    for warning in document["warnings"]:
        assert warning in checks


def test_a_report_into_a_missing_folder_exits_2_before_computing(capsys, tmp_path):
    code = cli.main(["run", "--report", str(tmp_path / "no" / "such" / "report.html")])
    err = capsys.readouterr().err
    assert code == 2 and "--report" in err and len(err.strip().splitlines()) == 1


BROWSERS = [name for name in ("chromium", "chromium-browser", "google-chrome", "firefox") if shutil.which(name)]


@pytest.mark.skipif(not BROWSERS, reason="no headless browser on this machine (CI has none either)")
def test_a_headless_browser_opens_the_report(capsys, tmp_path):
    """The page's DOM, as a headless browser builds it, holds the title and the results."""
    code, _, _, _, _ = _report(capsys, tmp_path, "gearbox_duty_cycle")
    dom = subprocess.run([BROWSERS[0], "--headless", "--disable-gpu", "--dump-dom", str(tmp_path / "report.html")],
                         capture_output=True, text=True, timeout=120).stdout
    assert code == 0 and "over a three-step duty cycle" in dom and "duty.life.L10" in dom


def test_the_report_marks_the_values_a_designation_estimated(capsys, tmp_path):
    """designation_6205 (a [bearing] of a designation alone): the inputs' "from" column names the
    standard's table of d, D, B and marks each estimated value ESTIMATED with how, as the JSON does."""
    code, _, _, parsed, document = _report(capsys, tmp_path, "designation_6205")
    inputs = "".join(parsed.sections["Inputs"])
    assert code == 0 and "designation 6205: GOST 8338-75 Table 5" in inputs
    for key, source in document["derived"].items():
        assert key in inputs and source in inputs
    assert sum(source.startswith("ESTIMATED") for source in document["derived"].values()) == 6
