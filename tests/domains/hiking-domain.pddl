; Hiking-like (after IPC 2014 hiking): a couple walks a trail together, two distinct people.
; Equality: (not (= ?p1 ?p2)) and (not (= ?x ?y)). None of these predicates has paraphrases.
(define (domain hiking)
  (:requirements :typing :equality :negative-preconditions)
  (:types person car tent place)
  (:predicates (at-person ?p - person ?x - place) (at-car ?c - car ?x - place) (at-tent ?t - tent ?x - place)
               (up ?t - tent) (down ?t - tent) (next ?x ?y - place) (walked ?p - person ?x - place))
  (:action put-down
    :parameters (?p - person ?x - place ?t - tent)
    :precondition (and (at-person ?p ?x) (at-tent ?t ?x) (up ?t))
    :effect (and (down ?t) (not (up ?t))))
  (:action put-up
    :parameters (?p - person ?x - place ?t - tent)
    :precondition (and (at-person ?p ?x) (at-tent ?t ?x) (down ?t))
    :effect (and (up ?t) (not (down ?t))))
  (:action drive-tent
    :parameters (?p - person ?x ?y - place ?c - car ?t - tent)
    :precondition (and (not (= ?x ?y)) (at-person ?p ?x) (at-car ?c ?x) (at-tent ?t ?x) (down ?t))
    :effect (and (at-person ?p ?y) (not (at-person ?p ?x)) (at-car ?c ?y) (not (at-car ?c ?x))
                 (at-tent ?t ?y) (not (at-tent ?t ?x))))
  (:action drive
    :parameters (?p - person ?x ?y - place ?c - car)
    :precondition (and (not (= ?x ?y)) (at-person ?p ?x) (at-car ?c ?x))
    :effect (and (at-person ?p ?y) (not (at-person ?p ?x)) (at-car ?c ?y) (not (at-car ?c ?x))))
  (:action walk-together
    :parameters (?t - tent ?y - place ?p1 - person ?x - place ?p2 - person)
    :precondition (and (not (= ?p1 ?p2)) (at-tent ?t ?y) (up ?t) (at-person ?p1 ?x) (next ?x ?y)
                       (at-person ?p2 ?x))
    :effect (and (at-person ?p1 ?y) (not (at-person ?p1 ?x)) (at-person ?p2 ?y) (not (at-person ?p2 ?x))
                 (walked ?p1 ?y) (walked ?p2 ?y))))
