"""Stage 2, optimal wingbeats: cost, optimisers, table builds, lookup tables."""
