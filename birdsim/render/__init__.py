"""Stage 5, pictures: GL selection, offscreen renderer, overlay, MP4."""
