"""IEEE 1516-2010's data distribution management (§9), a part of RTIambassador: regions over the FOM
modules' dimensions, on the core's HLA 1.3 routing spaces.

The modules' dimensions are one space (HLAdimensions), a region's range [lower, upper) is the core's closed
[lower, upper - 1], and a dimension a region does not name spans its whole axis, so regions overlap as IEEE
1516-2010 has it. An attribute of an object is updated in any number of regions (an association adds to
them, an unassociation removes the pairs it names) and an interaction is sent in any number: a subscriber
receives either once when one of its regions overlaps one of them; none is the default region, the whole
space."""

from __future__ import annotations

from typing import Any, Dict, Iterable, List, Mapping, Optional, Set, Tuple

from .. import _core
from .. import rti as _rti13
from . import _exceptions as x
from ._callbacks import Adapter
from ._handles import (AttributeHandle, DimensionHandle, InteractionClassHandle, MessageRetractionHandle,
                       ObjectClassHandle, ObjectInstanceHandle, ParameterHandle, RegionHandle, core, cores, wrap_set)
from ._support import services, tag_of, values_of

_DIMENSIONS = "HLAdimensions"  # the routing space of the FOM modules' dimensions (cpp/fed_parser/fom.hpp)


@services
class Regions:
    """The region services; RTIambassador provides the connection, the time conversion and the regions'
    table."""

    _adapter: Optional[Adapter]
    _regions: Dict[int, Dict[Any, Tuple[int, int]]]  # region -> dimension -> [lower, upper)

    def _inner(self) -> _rti13.RTIAmbassador:
        raise NotImplementedError

    def _time_in(self, time: Any) -> float:
        raise NotImplementedError

    def _timed(self, result: Any) -> Optional[MessageRetractionHandle]:
        raise NotImplementedError

    def _space(self) -> Any:
        inner = self._inner()
        try:
            return inner.getRoutingSpaceHandle(_DIMENSIONS)
        except _core.NameNotFound:
            raise x.InvalidDimensionHandle("InvalidDimensionHandle: the FOM modules declare no dimension") from None

    def _region(self, region: Any) -> Tuple[Any, Dict[Any, Tuple[int, int]]]:
        inner = core(RegionHandle, region)
        ranges = self._regions.get(int(inner))
        if ranges is None:
            raise x.RegionNotCreatedByThisFederate(f"RegionNotCreatedByThisFederate: {region!r}")
        return inner, ranges

    def _extent(self, ranges: Dict[Any, Tuple[int, int]]) -> List[Tuple[Any, Tuple[int, int]]]:
        return [(d, (lower, upper - 1)) for d, (lower, upper) in ranges.items()]

    def getDimensionHandle(self, theName: str) -> DimensionHandle:
        """The handle of a dimension by its name."""
        return DimensionHandle.wrap(self._inner().getDimensionHandle(theName, self._space()))

    def getDimensionName(self, theHandle: Any) -> str:
        """A dimension's name."""
        return self._inner().getDimensionName(core(DimensionHandle, theHandle), self._space())

    def getDimensionUpperBound(self, theHandle: Any) -> int:
        """A dimension's upper bound: its ranges lie in [0, upper bound)."""
        return int(self._inner()._dimension_upper_bound(core(DimensionHandle, theHandle), self._space()))

    def _dimensions_of(self, space: Any) -> Set[DimensionHandle]:
        """Every dimension, when `space` is the modules' (an attribute or class that names dimensions; 0: none)."""
        if int(space) == 0 or int(space) != int(self._space()):
            return set()
        found: Set[DimensionHandle] = set()
        h = 1
        while True:
            dimension = _core.DimensionHandle._from_int(h)
            try:
                self._inner().getDimensionName(dimension, space)
            except _core.DimensionNotDefined:
                return found
            found.add(DimensionHandle.wrap(dimension))
            h += 1

    def getAvailableDimensionsForClassAttribute(self, theClass: Any, theHandle: Any) -> Set[DimensionHandle]:
        """The dimensions of the attribute's regions: all of the modules' when it names any, else none."""
        return self._dimensions_of(self._inner().getAttributeRoutingSpaceHandle(core(AttributeHandle, theHandle),
                                                                                core(ObjectClassHandle, theClass)))

    def getAvailableDimensionsForInteractionClass(self, theClass: Any) -> Set[DimensionHandle]:
        """The dimensions of the interaction class's regions: all of the modules' when it names any."""
        return self._dimensions_of(self._inner().getInteractionRoutingSpaceHandle(core(InteractionClassHandle, theClass)))

    def createRegion(self, dimensions: Iterable[Any]) -> RegionHandle:
        """A region over these dimensions, each range its whole axis until set."""
        inner, space = self._inner(), self._space()
        ranges = {d: (0, int(inner._dimension_upper_bound(d, space))) for d in cores(DimensionHandle, dimensions)}
        region = inner.createRegion(space, self._extent(ranges))
        self._regions[int(region)] = ranges
        return RegionHandle.wrap(region)

    def getDimensionHandleSet(self, region: Any) -> Set[DimensionHandle]:
        """The dimensions of a region of this federate."""
        return wrap_set(DimensionHandle, self._region(region)[1])

    def getRangeBounds(self, region: Any, dimension: Any) -> Tuple[int, int]:
        """A region's range on a dimension, ``(lower, upper)``: upper excluded."""
        ranges = self._region(region)[1]
        d = core(DimensionHandle, dimension)
        if d not in ranges:
            raise x.RegionDoesNotContainSpecifiedDimension(f"RegionDoesNotContainSpecifiedDimension: {dimension!r}")
        return ranges[d]

    def setRangeBounds(self, region: Any, dimension: Any, rangeBounds: Tuple[int, int]) -> None:
        """Set a region's range on a dimension, ``(lower, upper)`` with upper excluded; it takes effect at
        :meth:`commitRegionModifications`."""
        self.getRangeBounds(region, dimension)
        lower, upper = (int(b) for b in rangeBounds)
        bound = self.getDimensionUpperBound(dimension)
        if not 0 <= lower < upper <= bound:
            raise x.InvalidRangeBound(f"InvalidRangeBound: ({lower}, {upper}) is not within [0, {bound}) with lower < upper")
        self._region(region)[1][core(DimensionHandle, dimension)] = (lower, upper)

    def commitRegionModifications(self, regions: Iterable[Any]) -> None:
        """The ranges set since the last commit take effect."""
        for region in regions:
            inner, ranges = self._region(region)
            self._inner().notifyAboutRegionModification(inner, self._extent(ranges))

    def deleteRegion(self, region: Any) -> None:
        """Delete a region no longer in use."""
        inner, _ranges = self._region(region)
        self._inner().deleteRegion(inner)
        del self._regions[int(inner)]

    def _region_pairs(self, pairs: Iterable[Any]) -> List[Tuple[List[Any], Any]]:
        """(attributes, regions) pairs as (core attributes, core region), one for each region of each pair."""
        return [(cores(AttributeHandle, attributes), self._region(r)[0])
                for attributes, regions in pairs for r in regions]

    def registerObjectInstanceWithRegions(self, theClass: Any, pairs: Iterable[Any],
                                          theObject: Optional[str] = None) -> ObjectInstanceHandle:
        """Register an object whose attributes update in these regions (an attribute in all the regions it is
        paired with)."""
        inner, adapter = self._inner(), self._adapter
        assert adapter is not None
        if theObject is not None and theObject not in adapter.reserved:
            raise x.ObjectInstanceNameNotReserved(f"ObjectInstanceNameNotReserved: {theObject!r} (reserve it first)")
        associated = [(a, region) for attributes, region in self._region_pairs(pairs) for a in attributes]
        handle = inner._register_object_with_regions(core(ObjectClassHandle, theClass), associated, theObject)
        adapter.reserved.discard(theObject or "")
        return ObjectInstanceHandle.wrap(handle)

    def associateRegionsForUpdates(self, theObject: Any, pairs: Iterable[Any]) -> None:
        """Update these attributes of the object in these regions too: their other regions stay."""
        for attributes, region in self._region_pairs(pairs):
            self._inner()._associate_region(region, core(ObjectInstanceHandle, theObject), attributes)

    def unassociateRegionsForUpdates(self, theObject: Any, pairs: Iterable[Any]) -> None:
        """Update these attributes of the object no longer in these regions; an attribute left with none is
        updated in the default region (the whole space)."""
        for attributes, region in self._region_pairs(pairs):
            if attributes:  # none named on the wire would be all of the object's (HLA 1.3)
                self._inner()._unassociate_region(region, core(ObjectInstanceHandle, theObject), attributes)

    def subscribeObjectClassAttributesWithRegions(self, theClass: Any, pairs: Iterable[Any], active: Any = True,
                                                  updateRateDesignator: str = "") -> None:
        """Subscribe to attributes of the class in these regions (with an update rate designator, as
        subscribeObjectClassAttributes)."""
        self._inner()._subscription_rate(core(ObjectClassHandle, theClass), updateRateDesignator)
        for attributes, regions in pairs:
            for region in regions:
                self._inner().subscribeObjectClassAttributesWithRegion(
                    core(ObjectClassHandle, theClass), self._region(region)[0], cores(AttributeHandle, attributes),
                    bool(active))

    def unsubscribeObjectClassAttributesWithRegions(self, theClass: Any, pairs: Iterable[Any]) -> None:
        """Stop subscribing in these regions (the core drops a region's attributes of a class together)."""
        for _attributes, regions in pairs:
            for region in regions:
                self._inner().unsubscribeObjectClassWithRegion(core(ObjectClassHandle, theClass), self._region(region)[0])

    def subscribeInteractionClassWithRegions(self, theClass: Any, regions: Iterable[Any], active: Any = True) -> None:
        """Subscribe to the interaction class in these regions."""
        for region in regions:
            self._inner().subscribeInteractionClassWithRegion(core(InteractionClassHandle, theClass),
                                                              self._region(region)[0], bool(active))

    def unsubscribeInteractionClassWithRegions(self, theClass: Any, regions: Iterable[Any]) -> None:
        """Stop subscribing to the interaction class in these regions."""
        for region in regions:
            self._inner().unsubscribeInteractionClassWithRegion(core(InteractionClassHandle, theClass),
                                                                self._region(region)[0])

    def sendInteractionWithRegions(self, theInteraction: Any, theParameterValues: Mapping[Any, Any], regions: Iterable[Any],
                                   theUserSuppliedTag: Any, theTime: Any = None) -> Optional[MessageRetractionHandle]:
        """Send an interaction in these regions: a subscriber receives it once when one of its regions overlaps
        one of them. With a time, timestamped, returning its retraction handle."""
        found = [self._region(r)[0] for r in regions]
        return self._timed(self._inner()._send_interaction_with_regions(
            core(InteractionClassHandle, theInteraction), values_of(ParameterHandle, theParameterValues), found,
            tag_of(theUserSuppliedTag), None if theTime is None else self._time_in(theTime)))

    def requestAttributeValueUpdateWithRegions(self, theClass: Any, pairs: Iterable[Any], theUserSuppliedTag: Any) -> None:
        """Ask the owners of these attributes of objects in these regions to provide them."""
        tag_of(theUserSuppliedTag)
        for attributes, regions in pairs:
            for region in regions:
                self._inner().requestClassAttributeValueUpdateWithRegion(
                    core(ObjectClassHandle, theClass), cores(AttributeHandle, attributes), self._region(region)[0])

