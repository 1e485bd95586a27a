"""The studies written into docs/ by ``slipmaps accuracy``: every map against the exact simulator
(accuracy), the iterations' convergence, variable stiffness and periodic gaits' stability."""
