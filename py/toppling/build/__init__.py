"""Building a scene: discs, the engine list, packing a polygon, bonds, joints, boundary conditions, column layouts."""
