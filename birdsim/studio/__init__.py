"""The studio and the 3-D view: a flight log as a three.js scene (``scene``), one
self-contained HTML page (``page``), the local web app (``app``, needs ``birdsim[studio]``)."""
