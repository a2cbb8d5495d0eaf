"""Random regions through the in-process gateway against an independent model of HLA 1.3 region overlap
(docs/ddm.md): every subscriber discovers and reflects exactly the instances whose update region overlaps
its subscription region, and receives exactly the interactions sent in an overlapping region."""

from __future__ import annotations

import itertools
from typing import Iterator, Optional

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import hlacore
import hlacore.rti as rti

from support import DATA, Federate, barrier

DDM_FED = str(DATA / "ddm.fed")
Extent = dict[str, tuple[int, int]]  # dimension name -> closed range; absent dimensions span the axis

# Small coordinates, so that touching and disjoint ranges are both frequent.
ranges = st.tuples(st.integers(0, 12), st.integers(0, 12)).map(lambda r: (min(r), max(r)))
extents = st.dictionaries(st.sampled_from(["X", "Y"]), ranges)


def model_overlap(a: Optional[Extent], b: Optional[Extent]) -> bool:
    """None is the default region (the whole space)."""
    if a is None or b is None:
        return True
    whole = (rti.MIN_EXTENT, rti.MAX_EXTENT)
    for dim in ("X", "Y"):
        (alo, ahi), (blo, bhi) = a.get(dim, whole), b.get(dim, whole)
        if ahi < blo or bhi < alo:
            return False
    return True


@pytest.fixture(scope="module")
def gateway() -> Iterator[hlacore.Gateway]:
    with hlacore.Gateway(port=0) as gw:
        yield gw


_federations = itertools.count()


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(
    subscriptions=st.lists(extents, min_size=1, max_size=3),
    updates=st.lists(st.one_of(st.none(), extents), min_size=1, max_size=4),
    interactions=st.lists(extents, max_size=3),
)
def test_delivery_matches_the_overlap_model(
    gateway: hlacore.Gateway, subscriptions: list[Extent], updates: list[Optional[Extent]], interactions: list[Extent]
) -> None:
    name = f"Ddm{next(_federations)}"
    creator = rti.RTIAmbassador(gateway.address)
    creator.createFederationExecution(name, DDM_FED)
    feds: list[Federate] = []
    try:
        pub = Federate(gateway.address, "pub", name)
        feds.append(pub)
        geo = pub.rtia.getRoutingSpaceHandle("Geo")
        dims = {d: pub.rtia.getDimensionHandle(d, geo) for d in ("X", "Y")}
        vehicle = pub.rtia.getObjectClassHandle("vehicle")
        position = pub.rtia.getAttributeHandle("position", vehicle)
        radio = pub.rtia.getInteractionClassHandle("radio")
        text = pub.rtia.getParameterHandle("text", radio)

        def region_of(fed: Federate, extent: Extent) -> rti.RegionHandle:
            return fed.rtia.createRegion(geo, [(dims[d], r) for d, r in extent.items()])

        subs = []
        for i, extent in enumerate(subscriptions):
            sub = Federate(gateway.address, f"s{i}", name)
            feds.append(sub)
            region = region_of(sub, extent)
            sub.rtia.subscribeObjectClassAttributesWithRegion(vehicle, region, [position])
            sub.rtia.subscribeInteractionClassWithRegion(radio, region)
            barrier(sub.rtia)
            subs.append(sub)
        pub.rtia.publishObjectClass(vehicle, [position])
        pub.rtia.publishInteractionClass(radio)
        objects = []
        for j, extent in enumerate(updates):
            if extent is None:
                obj = pub.rtia.registerObjectInstance(vehicle, f"v{j}")
            else:
                obj = pub.rtia.registerObjectInstanceWithRegion(vehicle, [(position, region_of(pub, extent))], f"v{j}")
            pub.rtia.updateAttributeValues(obj, {position: b"%d" % j}, "")
            objects.append(obj)
        for k, extent in enumerate(interactions):
            pub.rtia.sendInteractionWithRegion(radio, {text: b"%d" % k}, region_of(pub, extent), "")
        # The gateway has routed everything once pub's round trip returns; each subscriber's own round trip
        # then comes back behind whatever was sent to it, and tick() delivers it all.
        barrier(pub.rtia)
        for i, sub in enumerate(subs):
            barrier(sub.rtia)
            sub.rtia.tick()
            expected = {f"v{j}" for j, extent in enumerate(updates) if model_overlap(subscriptions[i], extent)}
            assert {args[2] for args in sub.amb.named("discoverObjectInstance")} == expected
            assert sorted(args[1][position] for args in sub.amb.named("reflectAttributeValues")) == sorted(
                b"%d" % j for j, extent in enumerate(updates) if model_overlap(subscriptions[i], extent))
            assert sorted(args[1][text] for args in sub.amb.named("receiveInteraction")) == sorted(
                b"%d" % k for k, extent in enumerate(interactions) if model_overlap(subscriptions[i], extent))
    finally:
        for fed in feds:
            fed.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
        creator.destroyFederationExecution(name)
