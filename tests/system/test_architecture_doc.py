"""docs/architecture.md stays true where a count or a path can be checked: the update path's file count is
the files it lists, the check-and-send services are HLACORE_CLIENT_REQUESTS' count, and every repository path
it names exists."""

from __future__ import annotations

import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOC = (ROOT / "docs" / "architecture.md").read_text()
WORDS = {"two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7}


def section(title: str) -> str:
    start = DOC.index(f"## {title}\n")
    end = DOC.find("\n## ", start + 1)
    return DOC[start:end if end >= 0 else len(DOC)]


def listed_files(text: str) -> set[str]:
    """The files named at the head of each numbered item, before the dash: `cpp/...` and the short forms that
    follow a full one in the same item (`convert.hpp` after `cpp/bindings/objects.cpp`)."""
    files = set()
    for item in re.findall(r"^\d+\. (.*?) —", text, re.M):
        directory = ""
        for name in re.findall(r"`([^`]+)`", item):
            if "/" in name:
                directory = name.rsplit("/", 1)[0]
                files.add(name)
            else:
                files.add(f"{directory}/{name}")
    return files


def test_the_update_path_counts_the_files_it_lists() -> None:
    path = section("The path of an update")
    stated = int(re.search(r"is carried through (\d+) files", path).group(1))
    counted = path[:path.index("The bytes' way:")]
    files = listed_files(counted)
    assert len(files) == stated, sorted(files)
    for name in files:
        assert (ROOT / name).is_file(), name


def test_the_check_and_send_services_are_the_lists_count() -> None:
    stated = int(re.search(r"(\d+) services are written this way \(`HLACORE_CLIENT_REQUESTS`\)", DOC).group(1))
    header = (ROOT / "cpp" / "rti" / "wire" / "message_list.hpp").read_text()
    body = header.split("#define HLACORE_CLIENT_REQUESTS(X)")[1].split("\n\n")[0]
    assert stated == len(re.findall(r"X\((\w+)\)", body))


def test_adding_a_service_counts_its_steps() -> None:
    adding = section("Adding a service")
    word = re.search(r"touches (\w+) files", adding).group(1)
    assert WORDS[word] == len(re.findall(r"^\d+\. ", adding, re.M))


def test_every_path_it_names_exists() -> None:
    missing = []
    for name in sorted(set(re.findall(r"`((?:cpp|python|tests|docs|scripts|bench)/[^`*<> ]+)`", DOC))):
        name = name.rstrip("/")
        if "*" in name or not (ROOT / name).exists():
            missing.append(name)
    assert not missing, missing
