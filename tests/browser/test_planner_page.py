"""The planner page of `towdb serve` in a real browser: headless Chromium driven by
Selenium (Debian chromium, chromium-driver, python3-selenium), on loopback.

Test plan:
  browser-1  the page loads the stored vessels into the form; filled with the README's
             question it shows the answer `towdb query --json` gives (extreme tension,
             both checks), and draws the three charts (Chart.js instances with data,
             canvases with painted pixels); a screenshot is saved for the docs
  browser-2  a speed outside the stored data shows the server's message naming
             speed_kt and marks the speed field invalid
"""
import json
import os
import subprocess
import tempfile

import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select, WebDriverWait

SOURCE_DIR = os.environ["TOWDB_SOURCE_DIR"]
TOWDB = os.environ["TOWDB_EXE"]
DB = os.path.join(SOURCE_DIR, "db", "towdb.sqlite")
SCREENSHOT = os.environ.get("TOWDB_SCREENSHOT")  # where to save the page's picture (optional)
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--window-size=1300,1900"]


@pytest.fixture(scope="module")
def server():
    proc = subprocess.Popen([TOWDB, "serve", "--db", DB, "--port", "0"], stdout=subprocess.PIPE, text=True)
    line = proc.stdout.readline()
    assert "http://127.0.0.1:" in line, line
    url = line.split()[2]
    yield url
    proc.terminate()
    assert proc.wait(timeout=30) == 0


@pytest.fixture(scope="module")
def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in CHROMIUM_FLAGS:
        options.add_argument(flag)
    with tempfile.TemporaryDirectory(prefix="towdb-chromium-") as profile:
        options.add_argument(f"--user-data-dir={profile}")
        driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
        try:
            yield driver
        finally:
            driver.quit()


def fill(driver, question):
    for name in ("tug", "tow", "line"):
        Select(driver.find_element(By.ID, name)).select_by_visible_text(question[name])
    for name in ("length_ft", "speed_kt", "wind_kt", "heading_deg", "tow_days"):
        field = driver.find_element(By.ID, name)
        field.clear()
        field.send_keys(question[name])
    driver.find_element(By.ID, "ask").click()


def wait_state(driver, state):
    WebDriverWait(driver, 60).until(lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-state") == state)


README = dict(tug="T-ATF 166", tow="FFG 7", line="fiber", length_ft="1200", speed_kt="7", wind_kt="30",
              heading_deg="150", tow_days="1")


def test_answer_and_charts(server, browser):  # browser-1
    browser.get(server)
    wait_state(browser, "ready")
    fill(browser, README)
    wait_state(browser, "answered")
    cli = json.loads(subprocess.run([TOWDB, "query", "--db", DB, "--tug", "T-ATF", "--tow", "FFG7", "--line", "fiber",
                                     "--speed-kt", "7", "--wind-kt", "30", "--heading-deg", "150", "--length-ft",
                                     "1200", "--json"], capture_output=True, text=True, check=True).stdout)
    shown = browser.find_element(By.ID, "extreme-tension").text
    assert shown == f"{round(cli['extreme_tension_lbf']):,} lbf"
    assert browser.find_element(By.ID, "check-extreme").text.startswith("pass")
    assert browser.find_element(By.ID, "check-mean").text.startswith("pass")
    assert "T-ATF 166 towing FFG 7" in browser.find_element(By.ID, "answer-title").text
    depth = cli["catenary_depth_ft"]
    assert browser.find_element(By.ID, "depth").text == \
        f"{abs(depth):.1f} ft {'below' if depth >= 0 else 'above'} the waterline"
    for chart in ("chart-speed", "chart-heading", "chart-length"):
        points = browser.execute_script(
            "const c = Chart.getChart(arguments[0]); return c ? c.data.datasets.reduce((n, d) => n + d.data.length, 0) : 0;",
            chart)
        assert points > 20, chart
        painted = browser.execute_script(
            "const c = document.getElementById(arguments[0]); const d = c.getContext('2d')"
            ".getImageData(0, 0, c.width, c.height).data; let n = 0;"
            "for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++; return n;", chart)
        assert painted > 2000, chart  # lines, bands and axes drawn, not an empty canvas
    if SCREENSHOT:
        browser.save_screenshot(SCREENSHOT)


def test_bad_speed_names_the_field(server, browser):  # browser-2
    browser.get(server)
    wait_state(browser, "ready")
    fill(browser, dict(README, speed_kt="30"))
    wait_state(browser, "error")
    message = browser.find_element(By.ID, "error").text
    assert "speed_kt = 30 is outside the stored range" in message
    assert "invalid" in browser.find_element(By.ID, "speed_kt").get_attribute("class")
    assert not browser.find_element(By.ID, "answer").is_displayed()
