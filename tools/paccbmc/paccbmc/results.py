"""CBMC's --json-ui output: the properties, their status and, for a failed one, its trace."""
import json
from dataclasses import dataclass, field
from typing import List, Optional

REACH_PREFIX = "reach:"


@dataclass
class Property:
    name: str
    description: str
    status: str  # SUCCESS, FAILURE, UNKNOWN, ERROR
    trace: Optional[list] = field(default=None, repr=False)

    @property
    def is_reach(self) -> bool:
        """A reachability check: an assert of the negated outcome, which must FAIL (the outcome is reachable)."""
        return self.description.startswith(REACH_PREFIX)


def selected(show_properties_json: str, reach: bool) -> List[str]:
    """The names of the properties of `cbmc --show-properties --json-ui` that are reachability checks (reach) or
    that must hold (not reach): one part of a run split in two (paccbmc run --only), each given to CBMC as
    --property. The unwinding assertions are not among them: CBMC checks those in every part."""
    names = []
    for message in json.loads(show_properties_json):
        for item in message.get("properties", []) if isinstance(message, dict) else []:
            if item.get("description", "").startswith(REACH_PREFIX) == reach:
                names.append(item["name"])
    return names


def parse(text: str) -> List[Property]:
    """The properties of one CBMC run with --json-ui (and --trace for the failed ones' traces)."""
    messages = json.loads(text)
    props = []
    for message in messages:
        for item in message.get("result", []) if isinstance(message, dict) else []:
            props.append(Property(item["property"], item.get("description", ""), item["status"], item.get("trace")))
    errors = [m["messageText"] for m in messages
              if isinstance(m, dict) and m.get("messageType") == "ERROR" and "messageText" in m]
    if not props and errors:
        raise ValueError("CBMC reported errors: " + "; ".join(errors))
    return props


@dataclass
class Verdict:
    failed: List[Property]       # properties that must hold and do not
    unreached: List[Property]    # reachability checks whose outcome no path within the bound reaches
    known_open: List[Property]   # failed properties listed as known open defects
    held: int                    # properties that hold
    reached: int                 # reachability checks reached

    @property
    def ok(self) -> bool:
        return not self.failed and not self.unreached


def judge(props: List[Property], known_open=()) -> Verdict:
    """A property passes when it holds; a reachability check passes when it fails (its outcome is reachable).
    A property whose description starts with one of known_open may fail without failing the run."""
    failed, unreached, known, held, reached = [], [], [], 0, 0
    for prop in props:
        if prop.is_reach:
            if prop.status == "FAILURE":
                reached += 1
            else:
                unreached.append(prop)
        elif prop.status == "SUCCESS":
            held += 1
        elif prop.status == "FAILURE" and any(prop.description.startswith(k) for k in known_open):
            known.append(prop)
        else:
            failed.append(prop)
    return Verdict(failed, unreached, known, held, reached)
