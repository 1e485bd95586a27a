"""The exact simulator (the ground truth): the compiled DOP853 integrator, the hybrid stance and its
Jacobian, and the ``solve_ivp`` reference."""
