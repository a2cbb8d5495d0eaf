"""The HLA 1.3 .fed parser: dialects, CERTI handle numbering, name lookups, error positions, the lint CLI."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from hlacore import _core, fed
from hlacore._core import ErrorReadingFED

from support import TESTS

DATA = TESTS / "data" / "fed"
GOOD = DATA / "good"
BAD = DATA / "bad"

PAPER_ATTRIBUTES = [
    "privilegeToDelete", "id", "battery", "temperature", "sensor1", "sensor2", "sensor3",
    "location", "compass", "goto", "rotate", "activate",
]


def test_seed_fom_code1_handles() -> None:
    """Code 1 of the paper (with '( class' spacing) gives ObjectRoot=1, RTIprivate=2, robot=3 and attributes 1..12."""
    fom = fed.parse(GOOD / "testfed_paper.fed")
    assert (fom.federation_name, fom.fed_version) == ("TestFed", "v1.3")
    assert [(c.handle, c.qualified_name) for c in fom.object_classes] == [
        (1, "ObjectRoot"), (2, "RTIprivate"), (3, "robot"),
    ]
    robot = fom.object_class("robot")
    assert [(a.handle, a.name) for a in robot.attributes] == list(enumerate(PAPER_ATTRIBUTES, start=1))
    assert robot.attribute("battery").handle == 3
    assert robot.attribute("activate").handle == 12
    assert all(a.transport == "reliable" and a.order == "timestamp" and a.space is None for a in robot.attributes)
    assert fom.spaces == () and fom.interaction_classes == ()
    assert robot.parent == 1 and fom.object_class(1).children == (2, 3)


def test_papers_fom_under_certi_and_root_prefixed_lookup() -> None:
    """The papers' FOM in CERTI form: gps=8, activate=12, and 'ObjectRoot.robot' and 'robot' both resolve to 3."""
    fom = fed.parse(GOOD / "papers_certi.fed")
    robot = fom.object_class("ObjectRoot.robot")
    assert robot.handle == 3 and fom.object_class("robot") is robot
    assert robot.attribute("privilegeToDelete").handle == 1
    assert robot.attribute("gps").handle == 8
    assert robot.attribute("activate").handle == 12
    assert fom.object_class("HLAobjectRoot.robot") is robot


def test_certi_billard_dialect() -> None:
    """CERTI's Billard style (Fed/Class/Attribute capitalised, RELIABLE TIMESTAMP, Federate, Sec_Level) parses."""
    fom = fed.parse(GOOD / "billard_certi.fed")
    assert fom.federation_name == "Test"
    assert fom.space("Geo").handle == 1
    assert [(d.handle, d.name) for d in fom.space(1).dimensions] == [(1, "X"), (2, "Y")]
    assert [(c.handle, c.qualified_name) for c in fom.object_classes] == [
        (1, "ObjectRoot"), (2, "RTIprivate"), (3, "Bille"), (4, "Bille.Boule"),
    ]
    boule = fom.object_class("Boule")
    assert [(a.handle, a.name) for a in boule.attributes] == [
        (1, "privilegeToDelete"), (2, "PositionX"), (3, "PositionY"), (4, "Color"),
    ]
    root = fom.interaction_class("InteractionRoot")
    assert (root.handle, root.transport, root.order) == (1, "best_effort", "receive")
    bing = fom.interaction_class("InteractionRoot.Bing")
    assert (bing.handle, bing.transport, bing.order, bing.space) == (3, "reliable", "timestamp", "Geo")
    assert [(p.handle, p.name) for p in bing.parameters] == [(1, "BoulNum"), (2, "DX"), (3, "DY")]
    assert fom.interaction_class("RTIprivate").handle == 2 and fom.object_class("RTIprivate").handle == 2


def test_portico_dialect_and_inherited_parameters() -> None:
    """Portico style (lower case, '-' in names, v1_3) parses; subclasses repeat inherited handles then continue."""
    fom = fed.parse(GOOD / "portico_style.fed")
    assert (fom.federation_name, fom.fed_version) == ("Portico-Test", "v1_3")
    assert [s.name for s in fom.spaces] == ["TestSpace", "OtherSpace"]
    assert fom.space("OtherSpace").dimension("OtherDimension").handle == 1
    soda = fom.object_class("Food.Drink.Soda")
    assert soda.handle == 5 and fom.object_class("ObjectRoot.Food.Drink.Soda") is soda
    assert [(a.handle, a.name) for a in soda.attributes] == [
        (1, "privilegeToDelete"), (2, "calories"), (3, "volume"), (4, "flavor"), (5, "fizz"),
    ]
    assert soda.attribute("volume").space == "TestSpace" and soda.attribute("volume").transport == "best_effort"
    assert soda.attribute("fizz").space == "OtherSpace"
    chat = fom.interaction_class("Communication.Chat")
    assert [(p.handle, p.name) for p in chat.parameters] == [(1, "message"), (2, "sender")]
    assert fom.interaction_class("Communication").parameter("message").handle == 1
    assert [(c.handle, c.name) for c in fom.interaction_classes] == [
        (1, "InteractionRoot"), (2, "RTIprivate"), (3, "Communication"), (4, "Chat"), (5, "Finish"),
    ]
    assert fom.interaction_class("Finish").transport == "best_effort"
    assert fom.interaction_class(1).children == (2, 3, 5)


def test_openrti_dialect_any_section_order() -> None:
    """OpenRTI style: sections reordered, whitespace after '(', HLA roots, HLAreliable, keyword-like names."""
    fom = fed.parse(GOOD / "openrti_style.fed")
    assert fom.fed_version == "1_3"
    car = fom.object_class("HLAobjectRoot.Vehicle.Car")
    assert car.qualified_name == "Vehicle.Car" and car.handle == 3
    assert [(a.handle, a.name) for a in car.attributes] == [
        (1, "HLAprivilegeToDeleteObject"), (2, "speed"), (3, "timestamp"), (4, "reliable"),
    ]
    assert car.attribute("speed").transport == "best_effort" and car.attribute("speed").space == "Road"
    assert car.attribute("reliable").order == "receive"
    honk = fom.interaction_class("HLAinteractionRoot.Honk")
    assert (honk.transport, honk.order, honk.space) == ("best_effort", "timestamp", "Road")
    assert [p.name for p in honk.parameters] == ["volume", "receive"]
    assert fom.interaction_class("HLAinteractionRoot").transport == "reliable"
    assert [d.name for d in fom.space("Road").dimensions] == ["lane", "offset"]


def test_lookup_rules() -> None:
    """Lookups take handles, qualified names, root-prefixed names or a bare leaf (first declared wins); case matters."""
    fom = fed.parse_text(
        "(FED (Federation F) (FEDversion v1.3) (objects (class ObjectRoot"
        " (class A (class X (class Deep))) (class B (class X)))))"
    )
    assert [c.qualified_name for c in fom.object_classes] == ["ObjectRoot", "A", "A.X", "A.X.Deep", "B", "B.X"]
    assert fom.object_class("X").qualified_name == "A.X"
    assert fom.object_class("B.X").handle == 6
    assert fom.object_class("ObjectRoot.B.X").handle == 6
    assert fom.object_class("Deep").qualified_name == "A.X.Deep"
    assert fom.object_class("ObjectRoot").handle == 1
    assert fom.is_object_subclass("Deep", "A") and not fom.is_object_subclass("B.X", "A")
    for missing in ("a", "ObjectRoot.Deep", "C", 7, 0):
        with pytest.raises(KeyError):
            fom.object_class(missing)
    with pytest.raises(KeyError):
        fom.interaction_class("A")


def test_sections_optional_and_quoted_names() -> None:
    """Every section is optional and names or values may be quoted strings."""
    fom = fed.parse_text(
        '(FED (Federation "My Fed") (FEDversion "v1.3") (objects (class "ObjectRoot" (class "robot"))))'
    )
    assert fom.federation_name == "My Fed" and fom.fed_version == "v1.3"
    assert fom.object_class("robot").handle == 2
    assert fom.spaces == () and fom.interaction_classes == ()
    assert fed.parse_text("(FED (Federation a) (FEDversion b))").object_classes == ()


def test_crlf_bom_and_comments() -> None:
    """CRLF line endings, a UTF-8 byte order mark and ';;' comments anywhere (also at EOF) are accepted."""
    text = (
        "\ufeff;; header\r\n(FED ;; x\r\n (Federation F)\r\n (FEDversion v1.3) ;; y\r\n"
        " (objects (class ObjectRoot)))\r\n;; end"
    )
    assert fed.parse_text(text).object_class(1).name == "ObjectRoot"
    with pytest.raises(ErrorReadingFED) as info:
        fed.parse_text("\ufeff\r\n  x", "crlf.fed")
    assert str(info.value).startswith("crlf.fed:2:3: expected '(' to start the file")


BAD_FILES = [
    ("no_open_paren.fed", 1, 1, "expected '(' to start the file"),
    ("not_fed.fed", 1, 2, "expected keyword FED"),
    ("unknown_keyword.fed", 6, 8, "unknown keyword 'atribute'"),
    ("single_semicolon.fed", 1, 1, "invalid character ';' (comments start with ';;')"),
    ("unterminated_string.fed", 2, 25, "unterminated string"),
    ("unknown_transport.fed", 4, 33, "unknown transport 'relaible' (expected reliable or best_effort)"),
    ("unknown_order.fed", 1, 85, "unknown order 'tsoo' (expected timestamp or receive)"),
    ("missing_close.fed", 5, 1, "missing ')' to close '(class' opened at 3:5"),
    ("extra_close.fed", 3, 1, "unexpected ')'"),
    ("duplicate_class.fed", 5, 11, "duplicate object class 'robot'"),
    ("duplicate_attribute.fed", 4, 14, "duplicate attribute 'battery' in class 'robot'"),
    ("duplicate_inherited_attribute.fed", 7, 16, "duplicate attribute 'privilegeToDelete' in class 'robot'"),
    ("duplicate_parameter.fed", 6, 16, "duplicate parameter 'tag' in interaction class 'Ping'"),
    ("duplicate_section.fed", 3, 2, "duplicate section 'objects'"),
    ("attribute_outside_class.fed", 2, 11, "attribute outside an object class"),
    ("parameter_outside_interaction.fed", 2, 29, "parameter outside an interaction class"),
    ("unknown_space.fed", 3, 63, "unknown routing space 'Gep'"),
    ("unknown_space_declared_later.fed", 2, 56, "unknown routing space 'Geo'"),
    ("interaction_without_transport.fed", 2, 39,
     "interaction class 'InteractionRoot' needs a transport and an order"),
    ("trailing_text.fed", 3, 1, "unexpected text after the end of the FED"),
    ("empty.fed", 1, 1, "empty file"),
    ("invalid_name.fed", 1, 55, "invalid class name '3robot'"),
    ("missing_federation.fed", 1, 23, "no (Federation NAME) entry"),
    ("non_ascii.fed", 1, 66, "invalid character '\u03a9'"),
    ("attribute_after_subclass.fed", 5, 4, "attributes of class 'ObjectRoot' must come before its subclasses"),
]


@pytest.mark.parametrize(("name", "line", "column", "message"), BAD_FILES, ids=[b[0] for b in BAD_FILES])
def test_malformed_file_reports_position(name: str, line: int, column: int, message: str) -> None:
    """Each malformed fixture fails at the exact FILE:LINE:COL of the offending token with a specific message."""
    path = BAD / name
    with pytest.raises(ErrorReadingFED) as info:
        fed.parse(path)
    text = str(info.value)
    prefix = f"{path}:{line}:{column}: "
    assert text.startswith(prefix), text
    assert message in text[len(prefix):], text
    assert (info.value.file, info.value.line, info.value.column) == (str(path), line, column)


def test_every_bad_fixture_is_covered() -> None:
    """Every file under tests/data/fed/bad has an expectation, and every good fixture parses."""
    assert sorted(p.name for p in BAD.glob("*.fed")) == sorted(b[0] for b in BAD_FILES)
    for path in GOOD.glob("*.fed"):
        fed.parse(path)


def test_error_class_and_default_name() -> None:
    """ErrorReadingFED is an RTIexception; parse_text names the source '<string>' by default."""
    with pytest.raises(ErrorReadingFED) as info:
        fed.parse_text("  \n")
    assert isinstance(info.value, _core.RTIexception)
    assert str(info.value) == "<string>:1:1: empty file"


def test_nesting_limit() -> None:
    """Absurdly deep class nesting is an error rather than a stack overflow."""
    text = "(FED (Federation F) (FEDversion v) (objects " + "(class c " * 5000
    with pytest.raises(ErrorReadingFED, match="nested more than"):
        fed.parse_text(text)


def test_missing_file_raises_could_not_open(tmp_path: Path) -> None:
    """A missing file raises CouldNotOpenFED naming the path."""
    path = tmp_path / "absent.fed"
    with pytest.raises(_core.CouldNotOpenFED, match="absent.fed"):
        fed.parse(path)


def _run_cli(*args: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    return subprocess.run(
        [sys.executable, "-m", "hlacore.fed", *args], cwd=DATA, env=env, capture_output=True, text=True, timeout=60
    )


def test_lint_cli_reports_each_file() -> None:
    """python -m hlacore.fed prints 'FILE: ok (...)' for good files, compiler-form errors on stderr, exit 1."""
    result = _run_cli("good/testfed_paper.fed", "bad/unknown_order.fed", "good/billard_certi.fed", "missing.fed")
    assert result.returncode == 1
    assert result.stdout.splitlines() == [
        "good/testfed_paper.fed: ok (3 object classes, 0 interaction classes)",
        "good/billard_certi.fed: ok (4 object classes, 3 interaction classes)",
    ]
    errors = result.stderr.splitlines()
    assert len(errors) == 2
    assert errors[0].startswith("bad/unknown_order.fed:1:85: unknown order 'tsoo'")
    assert errors[1].startswith("missing.fed: ")


def test_lint_cli_exit_codes() -> None:
    """The CLI exits 0 when every file parses and 2 on a usage error."""
    ok = _run_cli("good/portico_style.fed", "good/openrti_style.fed")
    assert (ok.returncode, ok.stderr) == (0, "")
    assert len(ok.stdout.splitlines()) == 2
    assert _run_cli().returncode == 2
    assert _run_cli("--bogus", "good/portico_style.fed").returncode == 2


def test_generated_large_fom() -> None:
    """A generated FOM of 1000 object classes x 10 attributes parses with the right counts and handles."""
    parts = ["(FED (Federation Big) (FEDversion v1.3) (spaces (space Geo (dimension X)))\n",
             "(objects (class ObjectRoot (attribute privilegeToDelete reliable timestamp)\n"]
    for c in range(1000):
        attrs = " ".join(f"(attribute a{a} reliable timestamp Geo)" for a in range(10))
        parts.append(f"  (class C{c} {attrs})\n")
    parts.append("))\n(interactions (class InteractionRoot reliable receive)))\n")
    fom = fed.parse_text("".join(parts), "big.fed")
    assert len(fom.object_classes) == 1001
    assert sum(len(c.attributes) for c in fom.object_classes) == 1 + 1000 * 11
    last = fom.object_class("ObjectRoot.C999")
    assert last.handle == 1001
    assert [a.handle for a in last.attributes] == list(range(1, 12))
    assert last.attribute("a9").handle == 11 and last.attribute("a9").space == "Geo"
    assert len(fom.interaction_classes) == 1
