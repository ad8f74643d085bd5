"""Furniture from what the cameras saw: its joints, a drawer's and a compartment's free inside, its carcass."""
