"""The one place that renders Jinja2 templates (StrictUndefined: a typo in a template fails loudly)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import jinja2

TEMPLATE_DIR = Path(__file__).parent / "templates"


@lru_cache(maxsize=1)
def _environment() -> jinja2.Environment:
    return jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATE_DIR)),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=False,
    )


def template(template_name: str) -> jinja2.Template:
    """The template ``templates/<template_name>`` (its macros: ``template(name).module.<macro>``)."""
    return _environment().get_template(template_name)


def render(template_name: str, **data) -> str:
    """Render ``templates/<template_name>`` with ``data``."""
    return _environment().get_template(template_name).render(**data)
