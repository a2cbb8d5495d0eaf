"""Options are declared once, in the native core's tables: rtig's parsing and usage, hlacore.Gateway's and
hlacore.rti.RTIAmbassador's keywords, defaults and docs, and the reasons a value is refused all come from them."""

from __future__ import annotations

import inspect
import re
import subprocess

import pytest

import hlacore
from hlacore import _core, _options, rti

from support import rtig_executable


def words(text: str) -> str:
    return " ".join(text.split())


def same(python: str, table: str) -> bool:
    """Whether a keyword's default, as text, is the table's: numbers by value (30.0 is 30)."""
    try:
        return float(python) == float(table)
    except ValueError:
        return python == table


def rtig_help() -> str:
    return subprocess.run([rtig_executable(), "--help"], capture_output=True, text=True, timeout=30).stdout


@pytest.mark.parametrize("front, rows", [(hlacore.Gateway, _core.gateway_options()),
                                         (rti.RTIAmbassador, _core.client_options())], ids=["Gateway", "RTIAmbassador"])
def test_the_keywords_are_the_tables(front: type, rows: list[_options.Row]) -> None:
    """Every keyword of the front end is a row of its table and every row a keyword, with the table's default
    (None: the table's, or the environment's for the client); each row's help is in the class's docs."""
    parameters = dict(inspect.signature(front).parameters)
    assert sorted(parameters) == sorted(row[0] for row in rows)
    doc = words(inspect.getdoc(front) or "")
    for keyword, _spelled, metavar, repeated, default, help_text in rows:
        python_default = parameters[keyword].default
        if python_default is not None and not (repeated and not python_default):
            assert same(_options.texts(python_default)[0], default), keyword
        assert words(help_text) in doc, keyword


def test_rtig_usage_is_the_gateway_table() -> None:
    """rtig --help shows each of the gateway's options with its placeholder, help and default."""
    usage = words(rtig_help())
    for _keyword, flag, metavar, _repeated, default, help_text in _core.gateway_options():
        assert flag is not None
        assert f"[{flag}{' ' + metavar if metavar else ''}]" in usage, flag
        assert words(help_text) in usage, flag
        if metavar and default:
            assert f"{words(help_text)} (default {default})" in usage, flag


REFUSED = [("client_budget", 1000), ("stall_timeout", -1.0), ("frame_timeout", 0), ("max_frame", 1 << 31),
           ("max_datagram", 100), ("busy_poll_us", 2.5), ("port", 70000), ("save_dir", "")]


@pytest.mark.parametrize("keyword, value", REFUSED)
def test_rtig_and_the_gateway_refuse_a_value_for_the_same_reason(keyword: str, value: object) -> None:
    flag = next(row[1] for row in _core.gateway_options() if row[0] == keyword)
    with pytest.raises(ValueError) as refused:
        hlacore.Gateway(**{"port": 0, keyword: value})  # type: ignore[arg-type]
    assert str(refused.value).startswith(f"{keyword}='{value}': ")
    why = str(refused.value).split("': ", 1)[1]
    run = subprocess.run([rtig_executable(), flag, str(value)], capture_output=True, text=True, timeout=30)
    assert run.returncode == 2
    assert f"rtig: invalid {flag} '{value}': {why}\n" in run.stderr


def test_the_client_reads_each_variable_and_names_it_when_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    """A keyword wins over its variable; a variable's bad value is refused naming the variable."""
    for keyword, variable, _metavar, _repeated, _default, _help in _core.client_options():
        assert variable is not None and re.fullmatch(r"HLACORE_[A-Z_]+", variable), keyword
    monkeypatch.setenv("HLACORE_TIMEOUT", "soon")
    with pytest.raises(rti.RTIinternalError, match=r"^\$HLACORE_TIMEOUT='soon': must be a finite number of seconds"):
        rti._client_settings()
    assert rti._client_settings(timeout=2.5) is not None
    monkeypatch.delenv("HLACORE_TIMEOUT")
    monkeypatch.setenv("HLACORE_RTIG", "unix:/tmp/x.sock")
    settings = rti._client_settings()
    assert (settings.host, settings.port) == ("unix:/tmp/x.sock", 0)
    with pytest.raises(rti.RTIinternalError, match=r"^address='nowhere': is not HOST:PORT"):
        rti._client_settings(address="nowhere")
