"""pacrelease: cuts a release of the library (CHANGELOG.md, st/library.json, an annotated git tag) and
writes the release folder and archive of a commit (docs/release.md)."""
