"""The public API: parameters, validation, results, the index of maps, and the map and Jacobian calls."""
