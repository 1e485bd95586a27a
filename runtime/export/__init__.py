"""Exports of the compiled runtime to other languages (the C deadbeat solver's ctypes bindings)."""
