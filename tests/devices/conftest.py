"""Device tests drive build/pdp11 through harness/machine/simh.py (the root conftest makes
harness importable); their own helper modules (programs, plantio) live here."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
