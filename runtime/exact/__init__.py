"""The exact simulator's ``solve_ivp`` reference (the map ``"exact"``'s ``method="scipy"``); the compiled
simulator is the generator's support module ``exact_stance`` (derive/templates/exact_stance.py.j2)."""
