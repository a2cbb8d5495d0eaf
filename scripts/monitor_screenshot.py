"""Makes docs/monitor.png: the main job (``python -m hlacore.experiments.robot_in_the_loop``) run with ``--monitor``
at a watchable pace, its monitor page opened in Debian's headless chromium (Selenium) and captured midway.

usage: .venv/bin/python scripts/monitor_screenshot.py [OUT.png] (after ./scripts/test.sh, which installs
chromium, chromium-driver and Selenium)
"""

from __future__ import annotations

import pathlib
import shutil
import socket
import subprocess
import sys
import tempfile
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

REPO = pathlib.Path(__file__).resolve().parent.parent


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def main() -> int:
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else REPO / "docs" / "monitor.png"
    port = free_port()
    with tempfile.TemporaryDirectory() as work:
        job = subprocess.Popen([sys.executable, "-m", "hlacore.experiments.robot_in_the_loop", "--time-scale", "0.5",
                                "--monitor", f"127.0.0.1:{port}", "--out", f"{work}/run"],
                               stdout=subprocess.PIPE, text=True, stdin=subprocess.DEVNULL)
        try:
            assert job.stdout is not None
            url = None
            for line in job.stdout:
                if line.startswith("monitor: "):
                    url = line.split()[1]
                    break
            if url is None:
                raise SystemExit("the main job printed no monitor URL")
            options = webdriver.ChromeOptions()
            options.binary_location = shutil.which("chromium") or "chromium"
            for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1280,900"):
                options.add_argument(argument)
            driver = webdriver.Chrome(service=Service(executable_path=shutil.which("chromedriver") or "chromedriver"),
                                      options=options)
            try:
                driver.get(url)
                time.sleep(12.0)  # two minutes of chart would be more, but a dozen seconds shows the steps
                driver.save_screenshot(str(out))
            finally:
                driver.quit()
            for _ in job.stdout:
                pass
            return job.wait(300)
        finally:
            if job.poll() is None:
                job.kill()
                job.wait()


if __name__ == "__main__":
    sys.exit(main())
