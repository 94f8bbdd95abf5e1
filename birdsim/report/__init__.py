"""Stage 6, the dissertation's analysis: figure data, plots, claims, HTML."""
