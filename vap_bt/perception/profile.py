"""Perception profiles: for each predicate of a domain, which sense settles it and how the VLM is asked.

The paper verifies the household's predicates with five hand-written paraphrases each. Another
domain has other predicates, and one that shares a household name may mean something else (the
IPC ferry's ``on ?c``: the car is on the ferry). So each domain has a *profile*: a YAML file
beside it — ``domains/household.perception.yaml`` for ``domains/household.pddl``, or whatever a
task file's ``perception: file.yaml`` names — keyed by predicate name *and* arity::

    predicates:
      on/2:
        source: vlm
        origin: paper                 # who wrote the paraphrases (the report says so)
        paraphrases: ["Is the {X} on the {Y}?", ...]
      robot_in/1:
        source: proprioception
        note: localization says which room the base is in

A predicate's *source* says what settles it:

* ``vlm`` — the camera, through the VLM: the N paraphrases, the vote, view sufficiency and
  active perception. Without paraphrases in the file they are generated, by the backend when it
  can, else from templates (:mod:`vap_bt.perception.paraphrase`), and the report lists them;
* ``proprioception`` — the robot's own state (localization, the gripper);
* ``map`` — the site map's rigid facts (or a problem's static facts): nothing to look at;
* ``none`` — never checked.

Trees check exactly the ``vlm`` atoms; the others are recorded as unchecked with their source's
reason. A predicate the file leaves out — every predicate, for a domain without a file — gets
the default: ``map`` if no action changes it, else ``vlm``. So any domain's changing predicates
are verified, and no question is ever formatted with another predicate's text.

A profile also says which predicate plays which *role* the executive acts on (``roles:``; see
:mod:`vap_bt.domain.roles`): the one that says a thing is in view, that the gripper holds it or is
empty, that the robot is in a room, that a thing rests on or in another, which types can be
carried about and which is a room::

    roles:
      in_view: inview
      held: holding
      portable: [item]
      on: null                        # no predicate of this domain plays it: what needs it is off

A role the file leaves out gets the household's name, where the domain has that predicate with
the role's arity (else None: off).

A profile also says how the action-level baselines (SuccessVQA, AffordanceVQA) say each action
(``actions:``, keyed ``name/arity``, the same placeholders; an action left out is said with every
argument named)::

    actions:
      grasp/3: "grasp the {X} from the {Y}"

A file is checked in two steps, each fault one :class:`~vap_bt.errors.InputError` naming the
file and the field (exit code 2): its shape by pydantic and the paraphrases' placeholders
(:func:`load_spec`), then against the domain — the predicate exists with that arity, no two
predicates share a question, each role names a predicate of the role's arity or a type of the
domain (:func:`resolve`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Literal, Mapping, Sequence

from pydantic import BaseModel, ConfigDict, Field, create_model

from vap_bt.domain.atoms import Atom
from vap_bt.domain.knowledge import DomainKnowledge
from vap_bt.domain.roles import ARITY, HOUSEHOLD, Roles
from vap_bt.errors import InputError
from vap_bt.perception.paraphrase import (
    TEMPLATE_COUNT, paraphrases_problem, placeholder, template_paraphrases, template_problem, usable)
from vap_bt.perception.prompts import action_phrase, spoken
from vap_bt.perception.vlm import Paraphraser
from vap_bt.yaml_file import read_model

Source = Literal["vlm", "proprioception", "map", "none"]
#: a profile's file name beside its domain: ``household.pddl`` -> ``household.perception.yaml``
SUFFIX = ".perception.yaml"
#: the vote asks up to N = 5 paraphrases; a profile that writes its own gives at least that many
MIN_PARAPHRASES = TEMPLATE_COUNT
_KEY = re.compile(r"^([A-Za-z][A-Za-z0-9_\-]*)/(\d+)$")
_KEY_HINT = "keys are a predicate's name and arity, like on/2 or hand_empty/0"
_ACTION_KEY_HINT = "keys are an action's name and arity, like grasp/3 or open/1"
_DOMAIN_NAME = re.compile(r"\(\s*define\s*\(\s*domain\s+([^\s()]+)", re.I)


# -- the file ------------------------------------------------------------------------------------

class PredicateSpec(BaseModel):
    """One predicate's entry in a profile file."""

    model_config = ConfigDict(extra="forbid")
    source: Source
    paraphrases: list[str] = Field(default_factory=list, description="question templates: {X} first argument, {Y} second, ...")
    origin: str = Field("profile", description="who wrote the paraphrases: 'paper' (the appendix, verbatim), 'vap_bt', ...")
    note: str = Field("", description="why this source; reported with the atoms it leaves unchecked")


class _RolesFile(BaseModel):
    model_config = ConfigDict(extra="forbid")

    def over(self, base: Roles) -> Roles:
        """``base`` with the roles this file states (null ones switched off)."""
        given = {r: getattr(self, r) for r in self.model_fields_set}
        if "portable" in given:
            given["portable"] = tuple(given["portable"] or ())
        return replace(base, **given)


#: a profile file's ``roles:``: the predicate (or types) playing each role of
#: :class:`~vap_bt.domain.roles.Roles` (one field each, of the same name); null: none does; a role
#: left out keeps the household's name
RolesSpec = create_model("RolesSpec", __base__=_RolesFile, __doc__="A profile file's roles: (see :data:`RolesSpec`).",
                         **{f.name: (list[str] | None if f.name == "portable" else str | None, None)
                            for f in fields(Roles)})


class ProfileSpec(BaseModel):
    """A perception profile file: predicates keyed ``name/arity``, and the roles they play."""

    model_config = ConfigDict(extra="forbid")
    domain: str | None = Field(None, description="the PDDL domain's name; checked against the domain file when given")
    predicates: dict[str, PredicateSpec] = Field(default_factory=dict)
    roles: RolesSpec = Field(default_factory=RolesSpec, description="which predicate plays each role (vap_bt.domain.roles)")
    actions: dict[str, str] = Field(default_factory=dict, description=(
        "how an action-level question (SuccessVQA, AffordanceVQA) says each action: name/arity -> a phrase, "
        "{X} its first argument, {Y} its second, ...; an action left out is said by prompts.action_phrase"))


def load_spec(path: str | Path) -> ProfileSpec:
    """Read and check a profile file on its own (its keys, sources and paraphrases)."""
    path = Path(path)

    def keys_are_text(raw: dict) -> None:
        predicates = raw.get("predicates")
        for key in predicates if isinstance(predicates, dict) else ():
            if not isinstance(key, str):  # YAML 1.1 reads a bare on/off/yes/no as a boolean
                raise InputError(f"{path}: field predicates.{key}", _KEY_HINT)
        roles = raw.get("roles")
        for key, value in roles.items() if isinstance(roles, dict) else ():
            if isinstance(key, bool) or isinstance(value, bool):  # roles: {on: on} reads as {true: true}
                raise InputError(f"{path}: field roles" + ("" if isinstance(key, bool) else f".{key}"), "quote a role or predicate named on, off, yes or "
                                                               "no: YAML reads it bare as a boolean (\"on\": \"on\")")

    spec = read_model(path, ProfileSpec, "perception profile", "predicates: {name/arity: {source: ...}}",
                      keys_are_text)
    for key, entry in spec.predicates.items():
        m = _KEY.match(key)
        if m is None:
            raise InputError(f"{path}: field predicates.{key}", _KEY_HINT)
        if not entry.paraphrases:
            continue
        where = f"{path}: field predicates.{key}.paraphrases"
        why = paraphrases_problem(entry.paraphrases, int(m.group(2)))
        if why:
            raise InputError(where, why)
        if len(entry.paraphrases) < MIN_PARAPHRASES:
            raise InputError(where, f"{len(entry.paraphrases)} given; give at least {MIN_PARAPHRASES} (the vote "
                                    f"asks up to N = {MIN_PARAPHRASES}), or none to have them generated")
    for key, phrase in spec.actions.items():
        m = _KEY.match(key)
        if m is None:
            raise InputError(f"{path}: field actions.{key}", _ACTION_KEY_HINT)
        why = template_problem(phrase, int(m.group(2)), phrase=True)
        if why:
            raise InputError(f"{path}: field actions.{key}", why)
    return spec


def file_roles(path: str | Path | None) -> Roles:
    """The roles a profile file states over the household's, before any domain is read (a task
    file's scene is written out in these predicates; :func:`resolve` then checks them)."""
    return load_spec(path).roles.over(HOUSEHOLD) if path is not None else HOUSEHOLD


def locate(domain_file: str | Path) -> Path:
    """Where the profile of ``domain_file`` lies by convention (whether or not it exists)."""
    return Path(domain_file).with_suffix(SUFFIX)


# -- the resolved profile ------------------------------------------------------------------------

@dataclass(frozen=True)
class PredicatePerception:
    """How one predicate of the domain is perceived: its source, and the questions that ask it."""

    name: str
    types: tuple[str, ...]
    source: Source
    paraphrases: tuple[str, ...] = ()
    #: who wrote the paraphrases: "paper", "vap_bt", "profile", "templates", or the backend
    origin: str = ""
    generated: bool = False
    note: str = ""
    #: why a backend's paraphrases were not used, when templates stand in for them
    fallback: str = ""

    @property
    def arity(self) -> int:
        return len(self.types)

    @property
    def key(self) -> str:
        """``name/arity``: how a profile file names the predicate."""
        return f"{self.name}/{self.arity}"

    def questions(self, args: Sequence[str], n: int = TEMPLATE_COUNT) -> list[str]:
        """The first ``n`` paraphrases with ``args`` spoken in their places."""
        if len(args) != self.arity:
            raise ValueError(f"{self.key} takes {self.arity} arguments, got {tuple(args)}")
        if not self.paraphrases:
            raise ValueError(f"{self.key} has no paraphrases (source {self.source}): it is not asked of the VLM")
        names = {placeholder(i): spoken(a) for i, a in enumerate(args)}
        return [t.format(**names) for t in self.paraphrases[:n]]

    def unchecked_reason(self) -> str | None:
        """Why atoms of this predicate are not asked of the camera (None: they are)."""
        if self.source == "vlm":
            return None
        said = {"proprioception": "comes from the robot's own state (source proprioception), not from the camera",
                "map": "is map knowledge (source map), not looked at",
                "none": "is never checked (source none)"}[self.source]
        return f"{self.name!r} {said}" + (f": {self.note}" if self.note else "")

    def to_json(self) -> dict:
        out = {"predicate": self.key, "source": self.source}
        if self.paraphrases:
            out.update(origin=self.origin, generated=self.generated)
        if self.note:
            out["note"] = self.note
        return out


@dataclass(frozen=True)
class PerceptionProfile:
    """Every predicate of one domain with its source and paraphrases (:func:`resolve` builds it)."""

    predicates: Mapping[tuple[str, int], PredicatePerception]
    file: Path | None = None
    #: which predicate plays each role the executive acts on (default: the household's names)
    roles: Roles = field(default_factory=Roles)
    #: how action-level questions say an action, by (name, arity): a ``str.format`` phrase
    actions: Mapping[tuple[str, int], str] = field(default_factory=dict)

    def action_phrase(self, name: str, args: Sequence[str]) -> str:
        """``grasp(cup, coffee_table, kitchen)`` as the profile says it ("grasp the cup from the coffee
        table"), or plainly when it has no phrase for the action."""
        template = self.actions.get((name, len(args)))
        if template is None:
            return action_phrase(name, tuple(args))
        return template.format(**{placeholder(i): spoken(a) for i, a in enumerate(args)})

    def get(self, name: str, arity: int) -> PredicatePerception | None:
        """How ``name/arity`` is perceived; None for a predicate the domain does not have."""
        return self.predicates.get((name, arity))

    def source(self, name: str, arity: int) -> Source | None:
        """What settles atoms of ``name/arity``; None for a predicate the domain does not have."""
        p = self.get(name, arity)
        return p.source if p is not None else None

    def asks(self, name: str, arity: int) -> bool:
        """Whether atoms of ``name/arity`` are asked of the VLM."""
        return self.source(name, arity) == "vlm"

    def questions(self, atom: Atom, n: int = TEMPLATE_COUNT) -> list[str]:
        """The first ``n`` paraphrased questions for ``atom``."""
        p = self.get(atom.predicate, len(atom.args))
        if p is None:
            raise KeyError(f"{atom.predicate}/{len(atom.args)} is not a predicate of this profile's domain")
        return p.questions(atom.args, n)

    def unchecked_reason(self, atom: Atom) -> str | None:
        """Why ``atom`` is not asked of the camera, in words for the report; None when it is."""
        p = self.get(atom.predicate, len(atom.args))
        if p is None:
            return f"{atom.predicate}/{len(atom.args)} is not in the perception profile"
        return p.unchecked_reason()

    def generated(self) -> list[PredicatePerception]:
        """The predicates whose paraphrases were generated (by the backend or from templates), not written
        in a profile."""
        return [p for p in self.predicates.values() if p.generated]

    def to_json(self) -> dict:
        """For the report: the file, every predicate's source, and the paraphrases generated."""
        return {"file": str(self.file) if self.file else None,
                "predicates": [p.to_json() for p in self.predicates.values()],
                "generated": [{"predicate": p.key, "texts": list(p.paraphrases), "by": p.origin,
                               **({"fallback": p.fallback} if p.fallback else {})} for p in self.generated()]}


def resolve(knowledge: DomainKnowledge, path: str | Path | None = None,
            paraphraser: Paraphraser | None = None) -> PerceptionProfile:
    """The profile of ``knowledge``'s domain: the file at ``path`` (default: beside the domain
    file, if there is one), defaults for what it leaves out, paraphrases generated for ``vlm``
    predicates without any — by ``paraphraser`` when given and it answers usably, else from
    templates."""
    if path is None and knowledge.domain_file is not None and locate(knowledge.domain_file).is_file():
        path = locate(knowledge.domain_file)
    spec = load_spec(path) if path is not None else ProfileSpec()
    where = str(path) if path is not None else "perception profile"
    _check_domain(spec, knowledge, where)
    out: dict[tuple[str, int], PredicatePerception] = {}
    # what a backend writes must not repeat another predicate's question (the answer could not be
    # told apart): the file's texts are taken first, then each written one in turn
    taken = {t for e in spec.predicates.values() for t in e.paraphrases}
    for name, types in knowledge.predicates.items():
        entry = spec.predicates.get(f"{name}/{len(types)}")
        if entry is None:
            rigid = knowledge.is_rigid(name)
            entry = PredicateSpec(source="map" if rigid else "vlm", origin="",
                                  note="default for a predicate no action changes" if rigid else "")
        out[(name, len(types))] = p = _perception(name, tuple(types), entry, paraphraser, taken)
        taken |= set(p.paraphrases)
    _check_distinct(out.values(), where)
    roles = _roles(spec.roles, knowledge, where)
    actions = {(key.rsplit("/", 1)[0], int(key.rsplit("/", 1)[1])): phrase for key, phrase in spec.actions.items()}
    return PerceptionProfile(out, Path(path) if path is not None else None, roles, actions)


def _perception(name: str, types: tuple[str, ...], entry: PredicateSpec,
                paraphraser: Paraphraser | None, taken: set[str]) -> PredicatePerception:
    base = PredicatePerception(name, types, entry.source, tuple(entry.paraphrases), entry.origin, False, entry.note)
    if entry.source != "vlm" or entry.paraphrases:
        return base
    fallback = ""
    if paraphraser is not None:
        by = paraphraser_name(paraphraser)
        try:
            texts = paraphraser.paraphrase(name, types, TEMPLATE_COUNT)
        except Exception as exc:  # a backend's failure costs it the chance, never the run
            texts, fallback = None, f"{by} failed: {type(exc).__name__}: {exc}"
        texts = usable([t for t in texts if t not in taken], len(types), TEMPLATE_COUNT) \
            if isinstance(texts, (list, tuple)) else None
        if texts:
            return PredicatePerception(name, types, "vlm", tuple(texts), by, True, entry.note)
        fallback = fallback or f"{by} wrote no {TEMPLATE_COUNT} usable paraphrases"
    return PredicatePerception(name, types, "vlm", tuple(template_paraphrases(name, types)), "templates", True,
                               entry.note, fallback)


def paraphraser_name(p: Paraphraser) -> str:
    """Who generated paraphrases, for the report: the backend and its model."""
    try:
        model = p.describe().get("model")
    except Exception:
        model = None
    name = getattr(p, "name", type(p).__name__)
    return f"{name} ({model})" if model else str(name)


def _check_domain(spec: ProfileSpec, knowledge: DomainKnowledge, where: str) -> None:
    if spec.domain is not None and knowledge.domain_file is not None:
        m = _DOMAIN_NAME.search(Path(knowledge.domain_file).read_text())
        if m and m.group(1).lower() != spec.domain.lower():
            raise InputError(f"{where}: field domain", f"this profile is for {spec.domain!r}, "
                                                       f"but {knowledge.domain_file} defines {m.group(1)!r}")
    _check_named(spec.predicates, "predicates", "predicate", "argument",
                 {name: len(sig) for name, sig in knowledge.predicates.items()}, where)
    _check_named(spec.actions, "actions", "action", "parameter",
                 {name: len(schema.parameters) for name, schema in knowledge.schemas.items()}, where)


def _check_named(keys, section: str, noun: str, part: str, arities: dict[str, int], where: str) -> None:
    """Every ``name/arity`` key of a profile's ``section`` names a ``noun`` of the domain with that
    many ``part``s: one InputError naming the field otherwise."""
    for key in keys:
        name, arity = key.rsplit("/", 1)
        if name not in arities:
            raise InputError(f"{where}: field {section}.{key}",
                             f"the domain has no {noun} {name!r} (it has {', '.join(sorted(arities))})")
        n = arities[name]
        if n != int(arity):
            raise InputError(f"{where}: field {section}.{key}",
                             f"the domain's {name} takes {n} {part}{'s' if n != 1 else ''}: write {name}/{n}")


def _roles(spec: RolesSpec, knowledge: DomainKnowledge, where: str) -> Roles:
    """The household's roles the domain has, with what the file states over them, each checked:
    a stated predicate exists with the role's arity, a stated type exists."""
    for role in sorted(spec.model_fields_set):
        value = getattr(spec, role)
        names = value if isinstance(value, list) else [] if value is None else [value]
        for name in names:
            if role in ARITY:
                sig = knowledge.predicates.get(name)
                why = (f"the domain has no predicate {name!r}" if sig is None else
                       f"the role {role} takes {ARITY[role]} argument{'s' if ARITY[role] != 1 else ''}, "
                       f"the domain's {name} {len(sig)}" if len(sig) != ARITY[role] else "")
            else:
                why = "" if name in knowledge.parents else \
                    f"the domain has no type {name!r} (it has {', '.join(sorted(knowledge.parents))})"
            if why:
                raise InputError(f"{where}: field roles.{role}", why)
    return spec.over(HOUSEHOLD.for_domain(knowledge))


def _check_distinct(predicates, where: str) -> None:
    """No question text may ask about two predicates: the answer could not be told apart."""
    owner: dict[str, str] = {}
    for p in predicates:
        for t in p.paraphrases:
            if t in owner and owner[t] != p.key:
                what = f"its generated paraphrase {t!r}" if p.generated else repr(t)
                raise InputError(f"{where}: field predicates.{p.key}.paraphrases",
                                 f"{what} is also a paraphrase of {owner[t]}: a question must ask about one "
                                 f"predicate" + ("; write paraphrases for it" if p.generated else ""))
            owner[t] = p.key
