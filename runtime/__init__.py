"""slipmaps.runtime: exact hybrid simulation, apex-return maps built on the generated kernels, CLI."""
