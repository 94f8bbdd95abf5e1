"""Stage 1, physics: frames, the bird, aerodynamics, kinematic models, one wingbeat."""
