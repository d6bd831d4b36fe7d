"""Icons and translations, installed as ``shaperapp.resources``."""
