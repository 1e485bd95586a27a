"""Sphinx configuration of slipmaps' documentation site.

Build it (the ``docs`` extra installs the tools)::

    python -m pip install -e '.[docs]'
    python -m sphinx -W --keep-going -n -b html docs docs/_build/html

Pages are MyST Markdown. The pages that commands write (``slipmaps generate``: maps.md, equations.md;
``slipmaps accuracy``: accuracy.md, convergence.md, stiffness.md, stability.md, reproductions.md) are
pages of the site as they are, listed in a toctree, never copied; getting_started.md includes the
README's quick start, first map call and install extras by ``{include}`` between their headings
(every other section lives on a page of its own, the README links to it). The API reference is autodoc of
``slipmaps.__all__``, the CLI reference sphinx-argparse on :func:`slipmaps.runtime.cli.app.build_parser`.
"""

from __future__ import annotations

from importlib.metadata import version as _version

import slipmaps
from sphinx.pycode import ModuleAnalyzer

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
#: NumPy's and the standard library's types in the type hints (``numpy.ndarray``, written ``np.ndarray``
#: in some, ``pathlib.Path``, ``collections.abc.Mapping``). The build runs offline, without intersphinx
#: inventories, so they have no target; nothing of slipmaps is ignored.
nitpick_ignore = [("py:class", "pathlib.Path")]
nitpick_ignore_regex = [
    ("py:class", r"(numpy|np)\..*"),
    ("py:class", r"collections\.abc\..*"),
]


def _reexported_data_doc(app, what, name, obj, options, lines):
    """A constant re-exported by ``slipmaps`` (``slipmaps.HUMAN_RUNNER``) is documented by the ``#:``
    comment where it is defined; autodoc would otherwise show its type's docstring."""
    public = name.removeprefix("slipmaps.")
    if what != "data" or public not in slipmaps.__all__:
        return
    comment = ModuleAnalyzer.for_module(slipmaps._EXPORTS[public]).find_attr_docs().get(("", public))
    if comment:
        lines[:] = list(comment)


def _resolve_public(app, env, node, contnode):
    """A reference by a name's defining module (``slipmaps.runtime.api.results.Result``, from a type
    hint) or by its bare name (``FixedPoints``, in the docstring of a re-exported function, read in
    module ``slipmaps``) goes to where the site documents it: ``slipmaps.NAME`` for a public name,
    else the one documented object of that name. Ambiguous or undocumented names stay warnings."""
    if node.get("refdomain") != "py":
        return None
    target = node["reftarget"].lstrip(".~")
    name = target.rsplit(".", 1)[-1]
    domain = env.get_domain("py")
    if name in slipmaps.__all__ and (target == name or target.startswith("slipmaps.")):
        resolved = f"slipmaps.{name}"
    else:
        found = [full for full in domain.objects if full.endswith(f".{target}")]
        if len(found) != 1:
            return None
        resolved = found[0]
    return domain.resolve_xref(env, node["refdoc"], app.builder, node["reftype"], resolved, node, contnode)


def setup(app):
    app.connect("autodoc-process-docstring", _reexported_data_doc)
    app.connect("missing-reference", _resolve_public)
