"""paccbmc: the model-checking harnesses' runner and counterexample printer (docs/verification.md)."""
