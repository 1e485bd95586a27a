"""The SLIP model from first principles: mechanics (section 2.2) and ballistic flight (2.1, 2.2.2)."""
