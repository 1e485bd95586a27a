"""Analyses on top of the maps: periodic gaits (fixed points of the apex-return map) and their stability."""
