"""Stage 3, flight: manoeuvres, playback of tables along a manoeuvre."""
