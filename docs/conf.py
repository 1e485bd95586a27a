"""Sphinx configuration of slipmaps' documentation site.

Build it (the ``docs`` extra installs the tools)::

    python -m pip install -e '.[docs]'
    python -m sphinx -W --keep-going -n -b html docs docs/_build/html

Pages are MyST Markdown. The pages that commands write (``slipmaps generate``: maps.md, equations.md;
``slipmaps accuracy``: accuracy.md, convergence.md, stiffness.md, stability.md) are pages of the
site as they are, listed in a toctree, never copied; the README's sections are included by
``{include}`` between their headings. The API reference is autodoc of ``slipmaps.__all__``, the CLI
reference sphinx-argparse on :func:`slipmaps.runtime.cli.app.build_parser`.
"""

from __future__ import annotations

from importlib.metadata import version as _version

import slipmaps

project = "slipmaps"
author = "the slipmaps authors"
copyright = "slipmaps authors"  # noqa: A001 - Sphinx's name
release = _version("slipmaps")
version = release

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinxarg.ext",
]

source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "figures", "**.json"]

myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
# The pages link to each other's sections by their titles' slugs (``[...](conventions.md#events)``).
myst_heading_anchors = 3

autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_default_options = {"members": True, "undoc-members": False}
napoleon_google_docstring = False
napoleon_numpy_docstring = True

html_theme = "pydata_sphinx_theme"
html_title = f"slipmaps {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
}
html_static_path: list[str] = []

nitpicky = True
#: Third-party types named in signatures and docstrings. The site has no network access at build time
#: (no intersphinx inventories), so these would be unresolved references; nothing of slipmaps is here.
nitpick_ignore_regex = [
    ("py:class", r"(numpy|np)\..*"),
    ("py:class", r"(scipy|distributed|dask|pathlib|os)\..*"),
]

assert slipmaps.__all__  # the API reference documents these (tests/test_docs.py)
