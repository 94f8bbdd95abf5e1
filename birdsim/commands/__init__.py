"""One module per ``birdsim`` subcommand; each exposes ``register(subparsers)``."""
