; Briefcase world (after the IPC-2000 ADL domain): moving the briefcase moves what is in it
; (forall/when conditional effects). None of these predicates has paraphrases.
(define (domain briefcase)
  (:requirements :typing :negative-preconditions :conditional-effects :equality)
  (:types location portable)
  (:predicates (at-b ?l - location) (at ?o - portable ?l - location) (in ?o - portable))
  (:action move
    :parameters (?from ?to - location)
    :precondition (and (at-b ?from) (not (= ?from ?to)))
    :effect (and (at-b ?to) (not (at-b ?from))
                 (forall (?o - portable) (when (in ?o) (and (at ?o ?to) (not (at ?o ?from)))))))
  (:action take-out
    :parameters (?o - portable)
    :precondition (in ?o)
    :effect (not (in ?o)))
  (:action put-in
    :parameters (?o - portable ?l - location)
    :precondition (and (not (in ?o)) (at ?o ?l) (at-b ?l))
    :effect (in ?o)))
