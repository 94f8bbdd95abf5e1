"""Validation against measured birds: the data file of published measurements, the
trimmed level-flight sweep of a bird, and the scorecard that compares the two."""
