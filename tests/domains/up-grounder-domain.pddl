; Minimal reproducer of a unified-planning 1.3.0 grounder bug (GrounderHelper with
; prune_actions=True, _purge_items_list): when two static preconditions of an action both rule
; out the same object for one parameter, the object is removed from the candidate list twice and
; the second list.remove raises "ValueError: list.remove(x): x not in list". The IPC driverlog
; and elevators domains hit it (their drive/move actions have two static preconditions on one
; parameter). vap_bt grounds its own instances (vap_bt/domain/instances.py); the test
; tests/test_pddl_robustness.py::test_unified_plannings_grounder_still_fails_on_the_reproducer tells when
; upstream has fixed it.
(define (domain up-grounder)
  (:requirements :strips :typing)
  (:types place)
  (:predicates (road ?p - place) (paved ?p - place) (at ?p - place))
  (:action go
    :parameters (?p - place)
    :precondition (and (road ?p) (paved ?p))
    :effect (at ?p)))
