"""Where RTIAmbassador() connects when no address is given: $HLACORE_RTIG, then CERTI's variables."""

import pytest

from hlacore import rti


@pytest.fixture
def clean_environment(monkeypatch):
    for name in ("HLACORE_RTIG", "CERTI_HOST", "CERTI_TCP_PORT"):
        monkeypatch.delenv(name, raising=False)
    return monkeypatch


def test_certi_variables_name_the_gateway(inprocess_gateway, clean_environment):
    """A PyHLA script that sets CERTI_HOST and CERTI_TCP_PORT reaches the gateway unchanged."""
    host, port = inprocess_gateway.address.rsplit(":", 1)
    clean_environment.setenv("CERTI_HOST", host)
    clean_environment.setenv("CERTI_TCP_PORT", port)
    assert rti.RTIAmbassador().address == inprocess_gateway.address


def test_certi_port_alone_means_this_host(inprocess_gateway, clean_environment):
    clean_environment.setenv("CERTI_TCP_PORT", inprocess_gateway.address.rsplit(":", 1)[1])
    assert rti.RTIAmbassador().address == inprocess_gateway.address


def test_hlacore_rtig_comes_before_certi_variables(inprocess_gateway, clean_environment):
    clean_environment.setenv("HLACORE_RTIG", inprocess_gateway.address)
    clean_environment.setenv("CERTI_HOST", "192.0.2.1")  # TEST-NET-1: never reached
    clean_environment.setenv("CERTI_TCP_PORT", "1")
    assert rti.RTIAmbassador().address == inprocess_gateway.address


def test_certi_host_alone_takes_the_default_port(clean_environment):
    clean_environment.setenv("CERTI_HOST", "127.0.0.1")
    settings = rti._client_settings()
    assert (settings.host, settings.port) == ("127.0.0.1", 60400)


def test_bad_certi_port_is_a_clear_error(clean_environment):
    clean_environment.setenv("CERTI_TCP_PORT", "sixty")
    with pytest.raises(rti.RTIinternalError, match=r"\$CERTI_TCP_PORT='sixty': must be a whole number between 0 and 65535"):
        rti.RTIAmbassador()
