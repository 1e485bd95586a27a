"""Report section 5 (variable stiffness), one module per subsection (this package's modules are
imported in report order, which is the order their entries are registered in)."""

from . import sec5_1  # noqa: F401 (registers the section's equations)
