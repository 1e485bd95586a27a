"""slipmaps outside Python: the exported C library, compiled and called from Python (docs/c_export.md)."""
