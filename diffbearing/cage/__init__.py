"""The cage: pocket and land contacts, forces on the cage at a steady state, its orbit in time and its stability."""
