"""slipmaps.derive: SymPy derivations of the SLIP model and its approximate stance maps."""
