"""A generated .fed file for the FOM-parse benchmark: `classes` object classes under ObjectRoot, each
declaring `attributes` of its own; with levels > 1 they form a tree of fan-out `fanout` (subclasses inherit
their ancestors' attributes, as in real FOMs, so the parser builds longer attribute lists)."""

from __future__ import annotations


def generate_fed(classes: int, attributes: int, levels: int = 1, fanout: int = 10) -> str:
    lines = ["(FED", " (Federation Generated)", " (FEDversion v1.3)", " (spaces)", " (objects",
             "  (class ObjectRoot", "   (attribute privilegeToDelete reliable timestamp)", "   (class RTIprivate)"]
    made = 0

    def emit(depth: int, prefix: str) -> None:
        nonlocal made
        for i in range(fanout if levels > 1 else classes):
            if made == classes:
                return
            made += 1
            name = f"{prefix}c{i}"
            pad = " " * (3 + depth)
            lines.append(f"{pad}(class {name}")
            for a in range(attributes):
                order = "timestamp" if a % 2 else "receive"
                lines.append(f"{pad} (attribute d{depth}a{a} {'reliable' if a % 3 else 'best_effort'} {order})")
            if depth < levels - 1:
                emit(depth + 1, name + "_")
            lines[-1] += ")"

    while made < classes:
        emit(0, f"t{made}_")
    lines[-1] += "))"
    lines += [" (interactions", "  (class InteractionRoot reliable receive",
              "   (class RTIprivate reliable receive))))"]
    return "\n".join(lines) + "\n"
