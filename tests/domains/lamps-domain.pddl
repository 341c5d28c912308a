; Switching lamps off and on in rooms: the goal asks for lamps to be off (negative goals), and
; switch-off's only effect is a delete that the goal relies on.
(define (domain lamps)
  (:requirements :typing :negative-preconditions)
  (:types lamp room)
  (:predicates (turned_on ?l - lamp) (lamp-in ?l - lamp ?r - room) (robot-at ?r - room) (door ?a ?b - room))
  (:action go
    :parameters (?from ?to - room)
    :precondition (and (robot-at ?from) (door ?from ?to))
    :effect (and (robot-at ?to) (not (robot-at ?from))))
  (:action switch-off
    :parameters (?l - lamp ?r - room)
    :precondition (and (turned_on ?l) (lamp-in ?l ?r) (robot-at ?r))
    :effect (not (turned_on ?l)))
  (:action switch-on
    :parameters (?l - lamp ?r - room)
    :precondition (and (not (turned_on ?l)) (lamp-in ?l ?r) (robot-at ?r))
    :effect (turned_on ?l)))
