"""slipmaps outside Python: the exported C library (the maps, the deadbeat solver) compiled and called
from Python through ctypes (docs/c_export.md)."""
