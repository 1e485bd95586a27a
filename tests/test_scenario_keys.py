"""The scenario reference (docs/scenarios.md) is the loader's keys, documented: every key, no
other, and the defaults the loader gives."""

from __future__ import annotations

import math
import re
from pathlib import Path

from slipmaps.runtime.control.scenario_keys import KEY_DOCS, reference_markdown
from slipmaps.runtime.control.scenarios import KEYS, from_dict

DOCS = Path(__file__).resolve().parent.parent / "docs"


def test_every_accepted_key_is_documented_and_no_other():
    accepted = {(t, k) for t, keys in KEYS.items() if t != "params" for k in keys}
    assert accepted == set(KEY_DOCS)
    # in the loader's order too (the reference is written in KEY_DOCS' order)
    documented = [(t, k) for t, keys in KEYS.items() if t != "params" for k in keys]
    assert documented == list(KEY_DOCS) and list(KEYS)[-1] == "params"
    assert all(all(cell is not None for cell in doc[:4]) and doc[3] for doc in KEY_DOCS.values())


def test_the_site_page_is_the_generated_reference():
    page = (DOCS / "scenarios.md").read_text()
    block = re.search(r"<!-- scenario-keys:begin -->\n(.*)<!-- scenario-keys:end -->", page, re.S)
    assert block, "docs/scenarios.md lost its scenario-keys markers"
    assert block.group(1) == reference_markdown(), "regenerate the block from reference_markdown()"


def _as_toml(value) -> str | None:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, dict):
        return "{}" if not value else None
    return None if value is None else str(value)


def test_the_documented_defaults_are_the_loaders():
    sc = from_dict({})
    checked = 0
    for (table, key), (_, default, _, _, field) in KEY_DOCS.items():
        if field is None:
            continue
        value = getattr(sc, field)
        if value is None:  # a default that is a rule, not a value (l0, the map's controls, none)
            assert not re.fullmatch(r"[-+0-9.e]+", default), (table, key, default)
        elif isinstance(value, float):
            assert float(default) == value, (table, key, value, default)
        else:
            assert _as_toml(value) == default, (table, key, value, default)
        checked += 1
    assert checked >= 20
    assert math.isclose(float(KEY_DOCS["start", "height"][1]), sc.start_height)
