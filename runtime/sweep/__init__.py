"""Parameter sweeps (``slipmaps sweep``, :func:`slipmaps.sweep`, defined in :mod:`.run`): a grid or a
seeded sample of any map, in chunks computed from row indices, written as CSV or Parquet,
resumable, on a Dask cluster optionally. Nothing is imported here, so that the command line's
parser loads without the generated index."""
